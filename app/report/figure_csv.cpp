#include "report/figure_csv.h"

#include <sstream>

namespace swarmlab::report {
namespace {

/// A CSV field: quoted when it holds a comma or a quote.
std::string field(const std::string& text) {
  if (text.find_first_of(",\"") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string axis_name(const Axis& a) {
  return a.unit.empty() ? a.label : a.label + " (" + a.unit + ")";
}

}  // namespace

std::string csv_of(const Figure& figure) {
  std::ostringstream out;
  out.precision(8);
  // Every figure's panels share one x quantity, so the header names it.
  out << "panel,series," << field(figure.panels.empty() ? "x" : axis_name(figure.panels[0].x))
      << ",y\n";
  for (std::size_t p = 0; p < figure.panels.size(); ++p) {
    const Panel& panel = figure.panels[p];
    for (const Series& s : panel.series) {
      const std::string name = field(s.name.empty() ? axis_name(panel.y) : s.name);
      for (std::size_t i = 0; i < s.x.size(); ++i)
        out << p << ',' << name << ',' << s.x[i] << ',' << s.y[i] << '\n';
    }
  }
  return out.str();
}

}  // namespace swarmlab::report
