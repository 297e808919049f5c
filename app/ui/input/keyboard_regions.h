#pragma once
// The screen's regions for the keyboard, as desktop apps have them: F6 (or Ctrl+F6) moves to
// the next one, Shift+F6 to the previous, in reading order: the menu bar, the controls (or the
// compact layout's drawer), the transport bar, the 3D view, the read-outs, the timeline, the
// plots.
// Ctrl+Tab, ImGui's own window switch, is kept from ImGui: browsers take it for their tabs.

namespace swarmlab {

/// Moves the keyboard to the next (+1) or previous (-1) region shown, its focus visible.
void move_keyboard_region(int direction);
/// Before ImGui::NewFrame: a Tab held with Ctrl never reaches ImGui, so that no window switch
/// answers a key the browser keeps.
void keep_ctrl_tab_from_imgui();

}  // namespace swarmlab
