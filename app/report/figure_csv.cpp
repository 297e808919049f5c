#include "report/figure_csv.h"

#include "report/csv_field.h"
#include "report/provenance.h"

namespace swarmlab::report {
namespace {

std::string axis_name(const Axis& a) {
  return a.unit.empty() ? a.label : a.label + " (" + a.unit + ")";
}

}  // namespace

std::string csv_of(const Figure& figure) {
  // Every figure's panels share one x quantity, so the header names it.
  std::string out = csv_comment_lines(figure.made_by) + csv_text("panel") + "," + csv_text("series") + "," +
                    csv_text(figure.panels.empty() ? "x" : axis_name(figure.panels[0].x)) + "," +
                    csv_text("y") + "\n";
  for (std::size_t p = 0; p < figure.panels.size(); ++p) {
    const Panel& panel = figure.panels[p];
    const std::string index = csv_number_text(std::to_string(p));
    for (const Series& s : panel.series) {
      const std::string name = csv_text(s.name.empty() ? axis_name(panel.y) : s.name);
      for (std::size_t i = 0; i < s.x.size(); ++i)
        out += index + "," + name + "," + csv_number(s.x[i], 8) + "," + csv_number(s.y[i], 8) + "\n";
    }
  }
  return out;
}

}  // namespace swarmlab::report
