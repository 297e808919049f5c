#pragma once
// What a plot shows: its title, axes, series and fit lines, as plain data (no ImGui). The
// widget draws it (plot_widget.h), its export buttons save it (plot_export_menu.h) and
// plot_figure.h makes the SVG's figure of it, each from the same colours.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace swarmlab {

struct PlotSeries {
  std::string label;
  const std::vector<double>* x = nullptr;
  const std::vector<double>* y = nullptr;
  std::uint32_t colour = 0xffffffff;  ///< the palette's Colour::packed() (ImGui's ImU32)
  bool points = false;  ///< markers (stages of an expansion) instead of a line
  float thickness = 2.0f;
};

/// y = prefactor x^exponent, drawn across the visible x range.
struct PowerLawLine {
  std::string label;
  double prefactor = 1, exponent = 0;
  std::uint32_t colour = 0xffffffff;  ///< the palette's Colour::packed() (ImGui's ImU32)
};

struct PlotAxis {
  std::string label;  ///< quantity and unit, e.g. "t (time)"
  bool log = false;
  std::optional<double> min, max;  ///< fixed ends; otherwise from the data
};

struct PlotSpec {
  std::string title;       ///< as shown, in the language in use
  std::string file_title;  ///< the title in English, which names the saved files (empty: title)
  PlotAxis x, y;
  std::vector<PlotSeries> series;
  std::vector<PowerLawLine> fits;
  bool y_from_zero = false;  ///< include 0 in a linear y range (pressures, temperatures)
  std::string empty_message;  ///< shown in an empty plot (empty: "no data yet")
};

}  // namespace swarmlab
