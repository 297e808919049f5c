#pragma once
// The keyboard: one table of shortcuts that both runs them and lists them in the help window.

#include "ui/state/app_state.h"

namespace swarmlab {

/// Runs the shortcuts pressed this frame (not while a text field has the keyboard).
void handle_shortcuts(AppState& state);
/// The help window: every shortcut and the mouse controls.
void draw_help_window(AppState& state);

}  // namespace swarmlab
