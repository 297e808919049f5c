#pragma once
// A plot's context menu (right click): save it as SVG (drawn by the report's svg_plot from the
// plot's own data), as PNG (the pixels on screen), or its numbers as CSV (the report's
// panel,series,x,y). The plot widget knows no AppState, so the request waits here until the
// app takes it and opens the save dialog.

#include <imgui.h>

#include <optional>
#include <string>

#include "ui/plots/plot_widget.h"
#include "report/figure.h"

namespace swarmlab {

struct PlotExport {
  enum class Kind { svg, png, csv } kind = Kind::svg;
  std::string title;    ///< the plot's title, for the file name
  std::string content;  ///< SVG or CSV text; empty for PNG, read from the screen
  ImVec2 min, max;      ///< the plot's rectangle on screen (logical pixels), for PNG
};

/// The report figure of a plot: one panel, its series and fit lines, its axes.
report::Figure figure_of(const PlotSpec& spec);

/// The menu of the plot drawn over [min, max]; open: it was right-clicked this frame.
void plot_export_menu(const PlotSpec& spec, ImVec2 min, ImVec2 max, bool open);

struct AppState;

/// Once a frame: an SVG or CSV asked for goes to the save dialog (save_dialog.h); a PNG waits
/// for a frame drawn without the menu.
void handle_plot_export(AppState& state);
/// After the frame is drawn and before it is shown: reads a waiting PNG's pixels from the
/// framebuffer and hands the file to the save dialog (glReadPixels: desktop GL3 and WebGL2).
void capture_plot_png(AppState& state);

/// PNG bytes of an RGBA image stored bottom row first (as OpenGL reads it); empty on failure.
std::string png_of_gl_pixels(const unsigned char* rgba, int width, int height);

}  // namespace swarmlab
