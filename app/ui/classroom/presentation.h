#pragma once
// The projector and the classroom: presentation mode (the light theme, large text, the 3D view
// and one plot, the controls tucked away), the theme on its own, fullscreen and sound. These
// switch what AppState asks for; classroom_outputs.h carries it out on the window.

#include "ui/state/app_state.h"

namespace swarmlab {

/// The UI scale presentation mode starts at (at least): large enough for the back of a room.
constexpr float kPresentationUiScale = 1.5f;

/// On: remembers the panels, scale and theme and switches to the presentation; off: gives
/// them back.
void set_presentation(AppState& state, bool on);
void set_theme(AppState& state, Theme theme);
void set_sound(AppState& state, bool on);
void set_fullscreen(AppState& state, bool on);
/// The page was hidden (another tab, a minimised window, a tablet put to sleep) or shown again.
/// Hidden, a playing run pauses unless run_while_hidden; shown again after that pause, returns
/// true: the page tells the student why the run stands still.
bool set_page_hidden(AppState& state, bool hidden);

/// The View menu's entries for these (inside an open menu).
void draw_presentation_menu_items(AppState& state);
/// The transport bar's sound toggle (with the reason when sound cannot play).
void draw_sound_toggle(AppState& state);

}  // namespace swarmlab
