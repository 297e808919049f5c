#pragma once
// A plot's export: the buttons under it (Export CSV, Export PNG, Export SVG) and the same
// three in its right-click menu. SVG is drawn by the report's svg_plot from the plot's own data
// in its screen colours (plot_figure.h), PNG is the pixels on screen, CSV its numbers (the
// report's panel,series,x,y). Neither knows the AppState: the request waits here until the app
// takes it (plot_export.h) and opens the save dialog.

#include <imgui.h>

#include <optional>
#include <string>

#include "report/figure.h"
#include "ui/plots/plot_spec.h"

namespace swarmlab {

struct PlotExport {
  enum class Kind { svg, png, csv } kind = Kind::svg;
  std::string title;       ///< the plot's title as shown, for the save dialog
  std::string file_title;  ///< the plot's title in English, for the file name
  /// SVG and CSV: the plot's figure, written when the app takes the request (with what made
  /// it, which only the app knows); PNG is read from the screen.
  report::Figure figure;
  ImVec2 min, max;      ///< the plot's rectangle on screen (logical pixels), for PNG
};

/// The export buttons of the plot drawn over [min, max], on the line under it.
void plot_export_buttons(const PlotSpec& spec, ImVec2 min, ImVec2 max);

/// The menu of the plot drawn over [min, max]; open: it was right-clicked this frame.
void plot_export_menu(const PlotSpec& spec, ImVec2 min, ImVec2 max, bool open);

/// The export asked for in the menu since the last call, if any; it is no longer waiting.
std::optional<PlotExport> take_plot_export();

}  // namespace swarmlab
