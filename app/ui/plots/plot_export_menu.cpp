#include "ui/plots/plot_export_menu.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "report/figure_csv.h"
#include "report/svg_plot.h"

namespace swarmlab {
namespace {

std::optional<PlotExport> pending;  // asked for in the menu, not yet taken by the app

/// "P (force/area)" -> label "P", unit "force/area", as the report's axes carry them.
report::Axis axis_of(const PlotAxis& a, bool include_zero) {
  report::Axis axis;
  axis.log = a.log;
  axis.include_zero = include_zero && !a.log;
  const std::size_t open = a.label.rfind(" (");
  if (open != std::string::npos && a.label.back() == ')') {
    axis.label = a.label.substr(0, open);
    axis.unit = a.label.substr(open + 2, a.label.size() - open - 3);
  } else {
    axis.label = a.label;
  }
  return axis;
}

}  // namespace

report::Figure figure_of(const PlotSpec& spec) {
  report::Figure figure;
  figure.title = spec.title;
  report::Panel panel;
  panel.x = axis_of(spec.x, false);
  panel.y = axis_of(spec.y, spec.y_from_zero);
  double x_lo = INFINITY, x_hi = -INFINITY;
  int colour = 0;
  for (const PlotSeries& s : spec.series) {
    report::Series out;
    out.name = s.label;
    out.mark = s.points ? report::Mark::points : report::Mark::line;
    out.colour = colour++;
    const std::size_t n = std::min(s.x->size(), s.y->size());
    for (std::size_t i = 0; i < n; ++i) {
      const double x = (*s.x)[i];
      // The plot's scroll window: the figure shows what the plot shows.
      if ((spec.x.min && x < *spec.x.min) || (spec.x.max && x > *spec.x.max)) continue;
      out.x.push_back(x);
      out.y.push_back((*s.y)[i]);
      if (std::isfinite(x) && (!spec.x.log || x > 0))
        x_lo = std::min(x_lo, x), x_hi = std::max(x_hi, x);
    }
    panel.series.push_back(std::move(out));
  }
  for (const PowerLawLine& f : spec.fits) {
    if (!(x_lo < x_hi)) break;
    report::Series line;
    line.name = f.label;
    line.dashed = true;
    line.colour = colour++;
    for (int k = 0; k <= 64; ++k) {
      const double u = double(k) / 64;
      const double x = spec.x.log ? x_lo * std::pow(x_hi / x_lo, u) : x_lo + u * (x_hi - x_lo);
      line.x.push_back(x);
      line.y.push_back(f.prefactor * std::pow(x, f.exponent));
    }
    panel.series.push_back(std::move(line));
  }
  figure.panels.push_back(std::move(panel));
  return figure;
}

void plot_export_menu(const PlotSpec& spec, ImVec2 min, ImVec2 max, bool open) {
  if (open) ImGui::OpenPopup("plot menu");
  if (!ImGui::BeginPopup("plot menu")) return;
  ImGui::TextDisabled("%s", spec.title.c_str());
  PlotExport e;
  e.title = spec.title;
  e.min = min;
  e.max = max;
  if (ImGui::MenuItem("Save as SVG...")) {
    e.kind = PlotExport::Kind::svg;
    e.content = report::svg_of(figure_of(spec));
    pending = e;
  }
  if (ImGui::MenuItem("Save as PNG...")) {
    e.kind = PlotExport::Kind::png;  // read from the screen once the menu is gone
    pending = e;
  }
  if (ImGui::MenuItem("Save the numbers as CSV...")) {
    e.kind = PlotExport::Kind::csv;
    e.content = report::csv_of(figure_of(spec));
    pending = e;
  }
  ImGui::EndPopup();
}

std::optional<PlotExport> take_plot_export() { return std::exchange(pending, std::nullopt); }

}  // namespace swarmlab
