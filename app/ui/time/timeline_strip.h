#pragma once
// The timeline under the 3D view: the run so far as a bar to scrub (drag, or click) with the
// stage boundaries, the present and the furthest time reached; and the transport bar's time
// buttons (step back, fast-forward to the end of the stage or of the run).

#include "ui/state/app_state.h"

namespace swarmlab {

/// The strip's height in pixels (the view above it is that much shorter).
float timeline_strip_height();
/// Draws the strip in the rectangle (x, y, width, height) below the view.
void draw_timeline_strip(AppState& state, float x, float y, float width, float height);
/// Step back, back and forward by 1/100 of a period, fast-forward: for the transport bar.
void draw_time_buttons(AppState& state);

}  // namespace swarmlab
