#pragma once
// The scenario panel's storage buttons in the browser, in place of the desktop's path field
// with Open and Save (AppState::storage_controls).

#include "app_state.h"

namespace swarmlab {

/// Open preset... (a file picker), Download preset and Copy link.
void draw_storage_controls(AppState& state);

}  // namespace swarmlab
