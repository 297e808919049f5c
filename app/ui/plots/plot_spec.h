#pragma once
// What a plot shows: its title, axes, series and fit lines, as plain data. The widget draws it
// (plot_widget.h) and its right-click menu saves it (plot_export_menu.h) without needing the
// widget.

#include <imgui.h>

#include <optional>
#include <string>
#include <vector>

namespace swarmlab {

struct PlotSeries {
  std::string label;
  const std::vector<double>* x = nullptr;
  const std::vector<double>* y = nullptr;
  ImU32 colour = IM_COL32_WHITE;
  bool points = false;  ///< markers (stages of an expansion) instead of a line
  float thickness = 2.0f;
};

/// y = prefactor x^exponent, drawn across the visible x range.
struct PowerLawLine {
  std::string label;
  double prefactor = 1, exponent = 0;
  ImU32 colour = IM_COL32_WHITE;
};

struct PlotAxis {
  std::string label;  ///< quantity and unit, e.g. "t (time)"
  bool log = false;
  std::optional<double> min, max;  ///< fixed ends; otherwise from the data
};

struct PlotSpec {
  std::string title;
  PlotAxis x, y;
  std::vector<PlotSeries> series;
  std::vector<PowerLawLine> fits;
  bool y_from_zero = false;  ///< include 0 in a linear y range (pressures, temperatures)
  std::string empty_message = "no data yet";
};

}  // namespace swarmlab
