#pragma once
// A small plotting widget drawn with ImDrawList (no plotting library exists for ImGui 1.86 in
// Debian): lines or points, linear or log axes with ticks, labels and units, a legend, power-law
// fit lines and a hover read-out. Ticks follow the figures' rule (plotting/axis_ticks.h).

#include "ui/plots/plot_spec.h"

namespace swarmlab {

struct AppState;

/// Draws the plot at the cursor, full available width and the given height, in the app's
/// theme, with its export buttons on a line under it (within that height); an export asked for
/// waits in `state.plot_exports`. A height too small for a readable plot is raised to the least
/// that is (the panel scrolls). Returns whether the plot is hovered.
bool draw_plot(const char* id, const PlotSpec& spec, float height, AppState& state);

}  // namespace swarmlab
