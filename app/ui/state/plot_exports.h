#pragma once
// A plot's export on its way from the buttons and menu under the plot (plots/plot_export_menu.h)
// to the save dialog (plots/plot_export.h): the request waiting for the app, and a PNG waiting
// for a frame drawn without the menu. SVG is drawn by the report's svg_plot from the plot's own
// data in its screen colours, PNG is the pixels on screen, CSV its numbers (panel,series,x,y).

#include <optional>
#include <string>

#include "report/figure.h"

namespace swarmlab {

struct PlotExport {
  enum class Kind { svg, png, csv } kind = Kind::svg;
  std::string title;       ///< the plot's title as shown, for the save dialog
  std::string file_title;  ///< the plot's title in English, for the file name
  /// SVG and CSV: the plot's figure, written when the app takes the request (with what made
  /// it, which only the app knows); PNG is read from the screen.
  report::Figure figure;
  /// The plot's rectangle on screen (logical pixels), for PNG.
  float min_x = 0, min_y = 0, max_x = 0, max_y = 0;
};

struct PlotExports {
  std::optional<PlotExport> asked;  ///< by a button or the menu, not yet taken by the app
  std::optional<PlotExport> png;    ///< a PNG waiting for a frame drawn without the menu
  int png_frames_to_wait = 0;       ///< frames still to draw before the PNG is read
};

}  // namespace swarmlab
