#pragma once
// Tabs that wrap: where a row of tabs does not fit its window (a phone, a longer language's
// names), ImGui 1.86's tab bar would scroll them sideways, hiding some and cutting one off.
// Then the tabs are drawn as a strip of selectables that wraps onto further rows, each
// mirrored as a tab by the parallel DOM, so a person, Tab and a screen reader find the same
// tabs either way. Where they fit, ImGui's own tab bar draws them, as before.

#include <vector>

namespace swarmlab {

/// Whether tabs with these labels ("##" parts hidden) fit in one row of the current window.
bool tabs_fit(const std::vector<const char*>& labels);

/// Draws the tabs as a wrapping strip with `selected` shown selected; returns the tab pressed
/// this frame, or `selected` when none was.
int draw_wrapping_tabs(const std::vector<const char*>& labels, int selected);

}  // namespace swarmlab
