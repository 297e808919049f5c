#pragma once
// Placing a window on its rectangle of the screen layout, and recording it once drawn for
// swarmlab.state() (the browser's tests and the parallel page read where each panel is).

#include "ui/state/app_state.h"

namespace swarmlab {

/// Places the next window on r.
void place(const ScreenRect& r);
/// Records the current window under `name` in state.layout.panels.
void record_panel(AppState& state, const char* name);
/// The height the current window's content took, padding included.
float content_height();

}  // namespace swarmlab
