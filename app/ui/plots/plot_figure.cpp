#include "ui/plots/plot_figure.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

namespace swarmlab {
namespace {

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

std::string css_rgb(const Colour& c) {
  char text[8];
  std::snprintf(text, sizeof text, "#%02x%02x%02x", c.r, c.g, c.b);
  return text;
}

report::Figure figure_of(const PlotSpec& spec, const Palette& palette) {
  report::Figure figure;
  figure.title = spec.title;
  figure.ink.background = css_rgb(palette.plot_background);
  // The grid is drawn translucent on screen: the SVG gets its colour as blended there.
  figure.ink.grid = css_rgb(over(palette.plot_grid, palette.plot_background));
  figure.ink.frame = figure.ink.zero_line = css_rgb(over(palette.plot_axis, palette.plot_background));
  figure.ink.text = css_rgb(palette.plot_text);
  figure.ink.dim_text = css_rgb(palette.plot_dim_text);
  figure.ink.legend_border = css_rgb(over(palette.plot_axis, palette.plot_background));
  report::Panel panel;
  panel.x = axis_of(spec.x, false);
  panel.y = axis_of(spec.y, spec.y_from_zero);
  double x_lo = INFINITY, x_hi = -INFINITY;
  for (const PlotSeries& s : spec.series) {
    report::Series out;
    out.name = s.label;
    out.mark = s.points ? report::Mark::points : report::Mark::line;
    out.rgb = css_rgb(Colour::from_packed(s.colour));
    out.opacity = Colour::from_packed(s.colour).a / 255.0;
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
    line.rgb = css_rgb(Colour::from_packed(f.colour));
    line.opacity = Colour::from_packed(f.colour).a / 255.0;
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

}  // namespace swarmlab
