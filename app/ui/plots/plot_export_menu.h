#pragma once
// A plot's export: the buttons under it (Export CSV, Export PNG, Export SVG) and the same
// three in its right-click menu. The request (state/plot_exports.h) waits in
// AppState::plot_exports until the app takes it (plot_export.h) and opens the save dialog.

#include <imgui.h>

#include "ui/plots/plot_spec.h"

namespace swarmlab {

struct AppState;

/// The export buttons of the plot drawn over [min, max], on the line under it.
void plot_export_buttons(const PlotSpec& spec, ImVec2 min, ImVec2 max, AppState& state);

/// The menu of the plot drawn over [min, max]; open: it was right-clicked this frame.
void plot_export_menu(const PlotSpec& spec, ImVec2 min, ImVec2 max, bool open, AppState& state);

}  // namespace swarmlab
