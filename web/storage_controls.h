#pragma once
// The scenario panel's storage buttons in the browser, in place of the desktop's path field
// with Open and Save (AppState::storage_controls).

#include <string>

#include "ui/state/app_state.h"

namespace swarmlab {

/// Open preset... (a file picker), Download preset and Copy link.
void draw_storage_controls(AppState& state);

/// Where a button of the last frame was drawn, in CSS pixels from the canvas's top left
/// ("x y width height"; empty if not drawn), so that a test can click it like a person.
std::string storage_button_rect(const std::string& label);

}  // namespace swarmlab
