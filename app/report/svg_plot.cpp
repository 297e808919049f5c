#include "svg_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "plotting/axis_ticks.h"

namespace swarmlab::report {
namespace {

// Pixel layout. The plot area of a panel is kPanelUnit * Panel::height pixels tall.
constexpr double kPanelUnit = 400;
constexpr double kLeft = 88, kRight = 28, kTop = 48, kBottom = 58;
constexpr double kSharedGap = 14;  // between panels that share the x axis
constexpr double kNoteSpace = 20;  // above a panel that carries a note
constexpr double kSubtitleSpace = 18;
constexpr double kTickLength = 5;
constexpr double kLegendRow = 19, kLegendPad = 8, kLegendSample = 26;
constexpr double kLegendGap = 12;  // under a legend drawn below its panel
constexpr double kCharWidth = 6.9;  // an average 12 px DejaVu Sans character, for sizing boxes

// The matplotlib palette, which the paper's own figures appear to use (blue solid, orange
// dashed in its Fig. 5).
const char* const kPalette[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728",
                                "#9467bd", "#8c564b", "#e377c2", "#7f7f7f"};
const char* const kFont = "DejaVu Sans, Verdana, Arial, sans-serif";

const char* colour_of(int index) { return kPalette[std::abs(index) % 8]; }

std::string escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '&')
      out += "&amp;";
    else if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else
      out += c;
  }
  return out;
}

std::string px(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.1f", v);
  return buffer;
}

std::size_t glyph_count(const std::string& utf8) {
  return std::size_t(std::count_if(utf8.begin(), utf8.end(), [](char c) {
    return (static_cast<unsigned char>(c) & 0xC0) != 0x80;
  }));
}

bool usable(double v, bool log) { return std::isfinite(v) && (!log || v > 0); }

struct Extent {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  void add(double v) { lo = std::min(lo, v), hi = std::max(hi, v); }
  bool empty() const { return !(lo <= hi); }
};

/// The x or the y extent of a panel's points that can be drawn on its axes.
Extent extent_of(const Panel& p, std::vector<double> Series::*coordinate) {
  Extent e;
  for (const Series& s : p.series)
    for (std::size_t i = 0; i < s.x.size(); ++i)
      if (usable(s.x[i], p.x.log) && usable(s.y[i], p.y.log)) e.add((s.*coordinate)[i]);
  return e;
}

plotting::AxisRange range_of(const Extent& e, const Axis& axis) {
  plotting::RangeOptions options;
  options.log = axis.log;
  options.include_zero = axis.include_zero;
  return plotting::axis_range(e.lo, e.hi, options);
}

/// Maps data to pixels inside one panel's plot area.
struct PlotArea {
  double left, top, width, height;
  plotting::AxisRange xr, yr;
  bool xlog, ylog;

  static double fraction(double v, const plotting::AxisRange& r, bool log) {
    return log ? (std::log10(v) - std::log10(r.lo)) / (std::log10(r.hi) - std::log10(r.lo))
               : (v - r.lo) / (r.hi - r.lo);
  }
  double x(double v) const { return left + width * fraction(v, xr, xlog); }
  double y(double v) const { return top + height * (1 - fraction(v, yr, ylog)); }
};

/// Widens the narrower range so that one data unit spans as many pixels on x as on y.
void equalise_aspect(PlotArea& area) {
  const double x_span = area.xr.hi - area.xr.lo, y_span = area.yr.hi - area.yr.lo;
  const double scale = std::min(area.width / x_span, area.height / y_span);  // pixels per unit
  const double x_mid = 0.5 * (area.xr.lo + area.xr.hi), y_mid = 0.5 * (area.yr.lo + area.yr.hi);
  area.xr = {x_mid - 0.5 * area.width / scale, x_mid + 0.5 * area.width / scale};
  area.yr = {y_mid - 0.5 * area.height / scale, y_mid + 0.5 * area.height / scale};
}

std::string axis_title(const Axis& axis, const std::string& scale_suffix) {
  std::string in_brackets = axis.unit;
  if (!scale_suffix.empty()) in_brackets += (in_brackets.empty() ? "" : ", ") + scale_suffix;
  return in_brackets.empty() ? axis.label : axis.label + " (" + in_brackets + ")";
}

/// The series' own colour if it has one, else the palette's, as SVG attributes' values.
std::string colour_of(const Series& s) { return s.rgb.empty() ? colour_of(s.colour) : s.rgb; }
/// An opacity below 1 as an SVG attribute, else nothing.
std::string opacity_attribute(const char* attribute, double opacity) {
  if (opacity >= 1) return "";
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, " %s=\"%.2f\"", attribute, opacity);
  return buffer;
}

void draw_series(std::ostringstream& svg, const Series& s, const PlotArea& area) {
  const std::string colour = colour_of(s);
  const bool lines = s.mark != Mark::points;
  // Markers on a long line series would only blur it.
  const bool points =
      s.mark == Mark::points || (s.mark == Mark::line_and_points && s.x.size() <= 300);
  if (lines) {
    // Invalid points (a zero on a log axis) break the line rather than bridge the gap.
    std::vector<std::string> runs(1);
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (!usable(s.x[i], area.xlog) || !usable(s.y[i], area.ylog)) {
        if (!runs.back().empty()) runs.emplace_back();
        continue;
      }
      runs.back() += px(area.x(s.x[i])) + "," + px(area.y(s.y[i])) + " ";
    }
    for (const std::string& run : runs) {
      if (run.empty()) continue;
      svg << "<polyline fill=\"none\" stroke=\"" << colour << "\" stroke-width=\""
          << (s.thin ? "1" : "1.8") << "\" stroke-linejoin=\"round\""
          << opacity_attribute("stroke-opacity", (s.thin ? 0.55 : 1) * s.opacity)
          << (s.dashed ? " stroke-dasharray=\"7 4\"" : "") << " points=\"" << run << "\"/>\n";
    }
  }
  if (points) {
    svg << "<g fill=\"" << colour << "\"" << opacity_attribute("fill-opacity", s.opacity) << ">";
    for (std::size_t i = 0; i < s.x.size(); ++i)
      if (usable(s.x[i], area.xlog) && usable(s.y[i], area.ylog))
        svg << "<circle cx=\"" << px(area.x(s.x[i])) << "\" cy=\"" << px(area.y(s.y[i]))
            << "\" r=\"2.7\"/>";
    svg << "</g>\n";
  }
}

/// Where a panel's legend goes: the corner of the plot area that covers no drawn point, or,
/// when every corner would cover one, a box under the panel (under its axis title; between
/// two panels that share the x axis, in the gap it widens), and the figure grows to hold it,
/// so that no point is hidden.
struct LegendPlace {
  std::vector<const Series*> entries;
  double x = 0, y = 0, w = 0, h = 0;
  bool below = false;  ///< under the panel's axis labels, outside the plot area
};

/// How many of the panel's drawn points and line pieces fall inside the box.
long covered_in(const Panel& panel, const PlotArea& area, double x, double y, double w, double h) {
  long covered = 0;
  for (const Series& s : panel.series)
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (!usable(s.x[i], area.xlog) || !usable(s.y[i], area.ylog)) continue;
      // Lines cover the space between their points too: look along each segment.
      const bool segment = s.mark != Mark::points && i + 1 < s.x.size() &&
                           usable(s.x[i + 1], area.xlog) && usable(s.y[i + 1], area.ylog);
      const int samples = segment ? 12 : 1;
      for (int k = 0; k < samples; ++k) {
        const double a = double(k) / samples;
        const double X =
            segment ? (1 - a) * area.x(s.x[i]) + a * area.x(s.x[i + 1]) : area.x(s.x[i]);
        const double Y =
            segment ? (1 - a) * area.y(s.y[i]) + a * area.y(s.y[i + 1]) : area.y(s.y[i]);
        if (X >= x && X <= x + w && Y >= y && Y <= y + h) ++covered;
      }
    }
  return covered;
}

/// The legend's entries and box; `below_at` is the y where a legend under the panel starts.
LegendPlace place_legend(const Panel& panel, const PlotArea& area, double below_at) {
  LegendPlace place;
  double text_width = 0;
  for (const Series& s : panel.series)
    if (!s.name.empty()) {
      place.entries.push_back(&s);
      text_width = std::max(text_width, kCharWidth * double(glyph_count(s.name)));
    }
  if (place.entries.empty()) return place;
  place.w = kLegendPad * 3 + kLegendSample + text_width;
  place.h = kLegendPad * 2 + kLegendRow * double(place.entries.size()) - 4;
  const double inset = 8;
  const double right = area.left + area.width - place.w - inset, left = area.left + inset;
  const double top = area.top + inset, bottom = area.top + area.height - place.h - inset;
  const double corners[4][2] = {{right, top}, {left, top}, {right, bottom}, {left, bottom}};
  for (const auto& corner : corners)
    if (covered_in(panel, area, corner[0], corner[1], place.w, place.h) == 0) {
      place.x = corner[0], place.y = corner[1];
      return place;
    }
  place.below = true;
  place.x = area.left, place.y = below_at;
  return place;
}

void draw_legend(std::ostringstream& svg, const LegendPlace& place, const Ink& ink) {
  if (place.entries.empty()) return;
  svg << "<rect x=\"" << px(place.x) << "\" y=\"" << px(place.y) << "\" width=\"" << px(place.w)
      << "\" height=\"" << px(place.h)
      << "\" fill=\"" << ink.background << "\" fill-opacity=\"0.88\" stroke=\""
      << ink.legend_border << "\" rx=\"3\"/>\n";
  for (std::size_t i = 0; i < place.entries.size(); ++i) {
    const Series& s = *place.entries[i];
    const double row = place.y + kLegendPad + kLegendRow * (double(i) + 0.5) - 2;
    const double x0 = place.x + kLegendPad, x1 = x0 + kLegendSample;
    if (s.mark != Mark::points)
      svg << "<line x1=\"" << px(x0) << "\" y1=\"" << px(row) << "\" x2=\"" << px(x1) << "\" y2=\""
          << px(row) << "\" stroke=\"" << colour_of(s) << "\" stroke-width=\""
          << (s.thin ? "1" : "1.8") << "\"" << (s.dashed ? " stroke-dasharray=\"7 4\"" : "")
          << "/>";
    if (s.mark != Mark::line)
      svg << "<circle cx=\"" << px(0.5 * (x0 + x1)) << "\" cy=\"" << px(row) << "\" r=\"3\" fill=\""
          << colour_of(s) << "\"/>";
    svg << "<text x=\"" << px(x1 + kLegendPad) << "\" y=\"" << px(row + 4) << "\" font-size=\"12\" fill=\""
        << ink.text << "\">" << escaped(s.name) << "</text>\n";
  }
}

void draw_panel(std::ostringstream& svg, const Panel& panel, const PlotArea& area,
                const LegendPlace& legend, bool x_labels, int index, const Ink& ink) {
  const plotting::AxisTicks xt = plotting::ticks_for(area.xr, area.xlog),
                            yt = plotting::ticks_for(area.yr, area.ylog);
  const std::string clip = "plot" + std::to_string(index);
  svg << "<clipPath id=\"" << clip << "\"><rect x=\"" << px(area.left) << "\" y=\"" << px(area.top)
      << "\" width=\"" << px(area.width) << "\" height=\"" << px(area.height)
      << "\"/></clipPath>\n";

  // Grid first, so that data and frame lie on top of it.
  svg << "<g stroke=\"" << ink.grid << "\" stroke-width=\"1\">";
  for (double v : xt.values)
    svg << "<line x1=\"" << px(area.x(v)) << "\" y1=\"" << px(area.top) << "\" x2=\""
        << px(area.x(v)) << "\" y2=\"" << px(area.top + area.height) << "\"/>";
  for (double v : yt.values)
    svg << "<line x1=\"" << px(area.left) << "\" y1=\"" << px(area.y(v)) << "\" x2=\""
        << px(area.left + area.width) << "\" y2=\"" << px(area.y(v)) << "\"/>";
  svg << "</g>\n";
  if (panel.zero_line && !area.ylog && area.yr.lo < 0 && area.yr.hi > 0)
    svg << "<line x1=\"" << px(area.left) << "\" y1=\"" << px(area.y(0)) << "\" x2=\""
        << px(area.left + area.width) << "\" y2=\"" << px(area.y(0))
        << "\" stroke=\"" << ink.zero_line << "\" stroke-width=\"1\" stroke-dasharray=\"3 3\"/>\n";

  svg << "<g clip-path=\"url(#" << clip << ")\">\n";
  for (const Series& s : panel.series) draw_series(svg, s, area);
  svg << "</g>\n";
  svg << "<rect x=\"" << px(area.left) << "\" y=\"" << px(area.top) << "\" width=\""
      << px(area.width) << "\" height=\"" << px(area.height)
      << "\" fill=\"none\" stroke=\"" << ink.frame << "\"/>\n";

  const double bottom = area.top + area.height;
  svg << "<g stroke=\"" << ink.frame << "\">";
  for (double v : yt.values)
    svg << "<line x1=\"" << px(area.left - kTickLength) << "\" y1=\"" << px(area.y(v)) << "\" x2=\""
        << px(area.left) << "\" y2=\"" << px(area.y(v)) << "\"/>";
  for (double v : xt.values)
    svg << "<line x1=\"" << px(area.x(v)) << "\" y1=\"" << px(bottom) << "\" x2=\"" << px(area.x(v))
        << "\" y2=\"" << px(bottom + kTickLength) << "\"/>";
  svg << "</g>\n<g font-size=\"12\" fill=\"" << ink.text << "\">";
  for (std::size_t i = 0; i < yt.values.size(); ++i)
    svg << "<text x=\"" << px(area.left - kTickLength - 3) << "\" y=\""
        << px(area.y(yt.values[i]) + 4) << "\" text-anchor=\"end\">" << escaped(yt.labels[i])
        << "</text>";
  if (x_labels)
    for (std::size_t i = 0; i < xt.values.size(); ++i)
      svg << "<text x=\"" << px(area.x(xt.values[i])) << "\" y=\"" << px(bottom + kTickLength + 14)
          << "\" text-anchor=\"middle\">" << escaped(xt.labels[i]) << "</text>";
  svg << "</g>\n";

  const double y_mid = area.top + 0.5 * area.height;
  svg << "<text x=\"20\" y=\"" << px(y_mid) << "\" transform=\"rotate(-90 20 " << px(y_mid)
      << ")\" text-anchor=\"middle\" font-size=\"14\" fill=\"" << ink.text << "\">"
      << escaped(axis_title(panel.y, yt.scale_suffix)) << "</text>\n";
  if (x_labels)
    svg << "<text x=\"" << px(area.left + 0.5 * area.width) << "\" y=\"" << px(bottom + 44)
        << "\" text-anchor=\"middle\" font-size=\"14\" fill=\"" << ink.text << "\">"
        << escaped(axis_title(panel.x, xt.scale_suffix)) << "</text>\n";
  if (!panel.note.empty())
    svg << "<text x=\"" << px(area.left) << "\" y=\"" << px(area.top - 6)
        << "\" font-size=\"12\" fill=\"" << ink.dim_text << "\">" << escaped(panel.note)
        << "</text>\n";
  draw_legend(svg, legend, ink);
}

}  // namespace

std::string svg_of(const Figure& figure) {
  const double width = figure.width;
  const double plot_width = width - kLeft - kRight;

  Extent shared;
  if (figure.shared_x)
    for (const Panel& p : figure.panels) {
      const Extent e = extent_of(p, &Series::x);
      if (!e.empty()) shared.add(e.lo), shared.add(e.hi);
    }

  std::vector<PlotArea> areas;
  std::vector<LegendPlace> legends;
  double y = kTop + (figure.subtitle.empty() ? 0 : kSubtitleSpace);
  for (std::size_t i = 0; i < figure.panels.size(); ++i) {
    const Panel& p = figure.panels[i];
    if (!p.note.empty()) y += kNoteSpace;
    PlotArea area{kLeft,
                  y,
                  plot_width,
                  kPanelUnit * p.height,
                  range_of(figure.shared_x ? shared : extent_of(p, &Series::x), p.x),
                  range_of(extent_of(p, &Series::y), p.y),
                  p.x.log,
                  p.y.log};
    if (p.equal_aspect && !p.x.log && !p.y.log) equalise_aspect(area);
    areas.push_back(area);
    const bool last = i + 1 == figure.panels.size();
    y += area.height + (figure.shared_x && !last ? kSharedGap : kBottom);
    legends.push_back(place_legend(p, area, y));
    if (legends.back().below) y += legends.back().h + kLegendGap;
  }
  const double height = y + 6;

  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << px(width) << "\" height=\""
      << px(height) << "\" viewBox=\"0 0 " << px(width) << " " << px(height) << "\" font-family=\""
      << kFont << "\">\n";
  if (!figure.made_by.empty()) {
    svg << "<metadata id=\"provenance\">\n";
    for (const std::string& line : figure.made_by) svg << escaped(line) << "\n";
    svg << "</metadata>\n";
  }
  svg << "<rect width=\"100%\" height=\"100%\" fill=\"" << figure.ink.background << "\"/>\n";
  svg << "<text x=\"" << px(width / 2) << "\" y=\"28\" text-anchor=\"middle\" font-size=\"17\" fill=\""
      << figure.ink.text << "\">"
      << escaped(figure.title) << "</text>\n";
  if (!figure.subtitle.empty())
    svg << "<text x=\"" << px(width / 2) << "\" y=\"48\" text-anchor=\"middle\" font-size=\"13\" "
        << "fill=\"" << figure.ink.dim_text << "\">" << escaped(figure.subtitle) << "</text>\n";
  for (std::size_t i = 0; i < figure.panels.size(); ++i) {
    const bool x_labels = !figure.shared_x || i + 1 == figure.panels.size();
    draw_panel(svg, figure.panels[i], areas[i], legends[i], x_labels, int(i), figure.ink);
  }
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace swarmlab::report
