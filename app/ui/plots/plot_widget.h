#pragma once
// A small plotting widget drawn with ImDrawList (no plotting library exists for ImGui 1.86 in
// Debian): lines or points, linear or log axes with ticks, labels and units, a legend, power-law
// fit lines and a hover read-out. Ticks follow the figures' rule (plotting/axis_ticks.h).

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

/// Draws the plot at the cursor, full available width and the given height.
void draw_plot(const char* id, const PlotSpec& spec, float height);

}  // namespace swarmlab
