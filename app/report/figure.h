#pragma once
// What a report figure holds, independent of how it is drawn: panels stacked vertically, each
// with two axes and a few data series. svg_plot.h draws it, figure_csv.h writes its numbers.

#include <string>
#include <vector>

namespace swarmlab::report {

struct Axis {
  std::string label;          ///< the quantity, e.g. "volume V"
  std::string unit;           ///< e.g. "length³"; empty for a pure number
  bool log = false;           ///< logarithmic scale (values <= 0 are left out)
  bool include_zero = false;  ///< stretch a linear range to show 0, e.g. a pressure
};

enum class Mark { line, points, line_and_points };

struct Series {
  std::string name;  ///< legend entry; empty: not in the legend
  std::vector<double> x, y;
  Mark mark = Mark::line;
  int colour = 0;  ///< index into the palette, so the same quantity keeps its colour
  /// A colour given instead ("#rrggbb"), with its opacity: an app plot's line as on screen.
  std::string rgb{};
  double opacity = 1;
  bool dashed = false;
  bool thin = false;  ///< a guide line (e.g. a residual's connecting line) drawn lighter
};

struct Panel {
  Axis x, y;
  std::vector<Series> series{};
  double height = 1;          ///< relative to the other panels of the figure
  bool zero_line = false;     ///< a horizontal line at y = 0 (residuals, drifts)
  bool equal_aspect = false;  ///< one unit is as long on x as on y (orbits)
  std::string note{};         ///< a short line drawn above the panel, at its left
};

/// The colours a figure is drawn in besides its series: the defaults print black on white;
/// an app plot saved as SVG takes its theme's (ui/plots/plot_figure.h), so that it looks as on
/// screen.
struct Ink {
  std::string background = "white";
  std::string grid = "#e8e8e8";
  std::string frame = "#333333";       ///< the plot's frame and its ticks
  std::string zero_line = "#555555";
  std::string text = "#222222";        ///< title, tick labels, axis titles
  std::string dim_text = "#555555";    ///< subtitle and notes
  std::string legend_border = "#bbbbbb";
};

struct Figure {
  std::string title;
  std::string subtitle;  ///< e.g. the preset's name, drawn smaller under the title
  std::vector<Panel> panels;
  /// All panels share the x axis: one range, tick labels and axis label only at the bottom.
  bool shared_x = false;
  double width = 760;  ///< pixels; the height follows from the panels
  Ink ink{};
  /// What made it (provenance_lines, report/provenance.h): the SVG's <metadata> and the
  /// CSV's leading "# " lines. None: neither.
  std::vector<std::string> made_by{};
};

/// A figure and the file stem it is saved under.
struct NamedFigure {
  std::string name;  ///< file stem, e.g. "loglog-P-V"
  Figure figure;
};

}  // namespace swarmlab::report
