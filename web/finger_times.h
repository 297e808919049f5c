#pragma once
// The browser's finger events carry the page's own time of the touch (finger_times.cpp).

namespace swarmlab {

/// From now on every SDL finger event from the canvas (a CSS selector, "#canvas") carries the
/// page's time stamp of its touch event, in milliseconds.
void stamp_fingers_with_page_time(const char* canvas);

}  // namespace swarmlab
