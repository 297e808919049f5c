#include "ui/plots/plot_widget.h"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <limits>

#include "i18n/translator.h"
#include "plotting/axis_ticks.h"
#include "ui/kit/theme_style.h"
#include "ui/plots/plot_export_menu.h"
#include "ui/state/app_state.h"

namespace swarmlab {
namespace {

/// The plot's frame is never shorter than this many lines of text (four tick labels).
constexpr float kMinFrameLines = 5.0f;

/// Maps data values to pixels along one axis, linearly or logarithmically.
struct Scale {
  double lo = 0, hi = 1;  // in transformed units (log10 when log)
  bool log = false;
  float p0 = 0, p1 = 1;  // pixels of lo and hi

  double transform(double v) const { return log ? std::log10(v) : v; }
  bool usable(double v) const { return std::isfinite(v) && (!log || v > 0); }
  float pixel(double v) const { return p0 + float((transform(v) - lo) / (hi - lo)) * (p1 - p0); }
  double value(float px) const {
    const double u = lo + double(px - p0) / double(p1 - p0) * (hi - lo);
    return log ? std::pow(10.0, u) : u;
  }
  plotting::AxisRange range() const {
    return log ? plotting::AxisRange{std::pow(10.0, lo), std::pow(10.0, hi)}
               : plotting::AxisRange{lo, hi};
  }
  void set(const plotting::AxisRange& r) {
    lo = transform(r.lo);
    hi = transform(r.hi);
  }
};

/// The data range of one axis over every series: only points that can be drawn (both
/// coordinates finite, and positive on a log axis) and, for y, that lie in the x window (a
/// scrolling plot).
void data_range(const PlotSpec& spec, bool x_axis, const Scale& x_scale, double& lo, double& hi) {
  lo = std::numeric_limits<double>::infinity();
  hi = -lo;
  auto drawable = [](double v, const PlotAxis& axis) {
    return std::isfinite(v) && (!axis.log || v > 0);
  };
  for (const PlotSeries& s : spec.series) {
    const std::size_t n = std::min(s.x->size(), s.y->size());
    for (std::size_t i = 0; i < n; ++i) {
      const double xi = (*s.x)[i], yi = (*s.y)[i];
      if (!drawable(xi, spec.x) || !drawable(yi, spec.y)) continue;
      if (!x_axis && (xi < x_scale.value(x_scale.p0) || xi > x_scale.value(x_scale.p1))) continue;
      const double v = x_axis ? xi : yi;
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  }
}

/// The figures' range rule (plotting::axis_range) as a live plot wants it: 0 and a lone value
/// on the frame, since its pressures count up from nothing and its time axis starts at the
/// first sample; a wider margin, and a decade around a lone value on a log axis, so that a
/// first stage still gets ticks.
plotting::RangeOptions range_options(const PlotAxis& axis, bool from_zero,
                                     plotting::OneValue one_value) {
  plotting::RangeOptions options;
  options.log = axis.log;
  options.include_zero = from_zero;
  options.zero_on_frame = true;
  options.min = axis.min;
  options.max = axis.max;
  options.one_value = one_value;
  options.margin = 0.05;
  options.one_value_decades = 1;
  options.margin_around_one_value = false;
  return options;
}

/// A line of text with values, printed as `format` says, in the language's decimal separator.
void value_text(const char* format, ...) IM_FMTARGS(1);
void value_text(const char* format, ...) {
  char text[512];
  va_list args;
  va_start(args, format);
  std::vsnprintf(text, sizeof text, format, args);
  va_end(args);
  ImGui::TextUnformatted(translator().numbers(text).c_str());
}

}  // namespace

bool draw_plot(const char* id, const PlotSpec& spec, float height, AppState& state) {
  ImGui::PushID(id);
  // The theme's colours (access/theme_palette.h, held to WCAG AA by its test).
  const Palette& colours = palette(state.presentation.theme);
  const ImU32 kPlotBackground = colours.plot_background.packed();
  const ImU32 kGrid = colours.plot_grid.packed(), kAxis = colours.plot_axis.packed();
  const ImU32 kText = colours.plot_text.packed(), kDimText = colours.plot_dim_text.packed();
  const float font = ImGui::GetFontSize();
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const float width = std::max(ImGui::GetContentRegionAvail().x, 10 * font);

  // The legend goes in rows between the title and the frame, never over the data.
  struct LegendEntry {
    std::string label;
    ImU32 colour;
    bool dashed;
  };
  std::vector<LegendEntry> legend;
  if (spec.series.size() > 1 || !spec.fits.empty())
    for (const PlotSeries& s : spec.series) legend.push_back({s.label, s.colour, false});
  for (const PowerLawLine& f : spec.fits) legend.push_back({f.label, f.colour, true});
  const float legend_left = origin.x + 0.5f * font, legend_right = origin.x + width - 0.5f * font;
  int legend_rows = 0;
  {
    float x = legend_right;  // forces a first row
    for (const LegendEntry& e : legend) {
      const float w = 2.0f * font + ImGui::CalcTextSize(e.label.c_str()).x + 0.8f * font;
      if (x + w > legend_right) ++legend_rows, x = legend_left;
      x += w;
    }
  }
  // The y axis's label goes beside the title, or on a line of its own below it when the two
  // (with room for a scale like "x 10^-14") do not fit side by side.
  const float title_width = ImGui::CalcTextSize(spec.title.c_str()).x;
  const std::string log_mark = std::string("  ") + tr("[log]");
  const std::string y_label_base = spec.y.label + (spec.y.log ? log_mark : "");
  const bool y_label_below =
      title_width + 1.5f * font + ImGui::CalcTextSize(y_label_base.c_str()).x + 5.0f * font >
      width - 0.5f * font;
  const float legend_top = origin.y + (y_label_below ? 2.5f : 1.3f) * font;
  const float left = origin.x + 4.2f * font, right = origin.x + width - 0.6f * font;
  const float top = legend_top + 1.2f * font * float(legend_rows) + 0.4f * font;
  // The height asked for holds the plot and its line of export buttons. The frame never gets
  // less than kMinFrameLines lines of text: a panel too short for every plot scrolls (a
  // residuals plot once squashed to nothing on a tablet).
  const float buttons = ImGui::GetFrameHeightWithSpacing();
  height = std::max(height - buttons, (top - origin.y) + kMinFrameLines * font + 2.4f * font);
  const float bottom = origin.y + height - 2.4f * font;
  // Named "plot" for a screen reader (the parallel DOM), in the language in use.
  ImGui::InvisibleButton(tr_id("plot"), ImVec2(width, height));
  const bool hovered = ImGui::IsItemHovered();
  const bool right_clicked = ImGui::IsItemClicked(ImGuiMouseButton_Right);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(origin, ImVec2(origin.x + width, origin.y + height), kPlotBackground, 4.0f);
  draw->AddText(ImVec2(origin.x + 0.5f * font, origin.y + 0.2f * font), kText, spec.title.c_str());

  Scale xs{0, 1, spec.x.log, left, right};
  Scale ys{0, 1, spec.y.log, bottom, top};
  double lo, hi;
  data_range(spec, true, xs, lo, hi);
  const bool has_data = std::isfinite(lo);
  xs.set(plotting::axis_range(lo, hi, range_options(spec.x, false, plotting::OneValue::at_start)));
  data_range(spec, false, xs, lo, hi);
  ys.set(plotting::axis_range(
      lo, hi, range_options(spec.y, spec.y_from_zero, plotting::OneValue::centred)));

  // Grid, ticks and their labels: the figures' tick rule, with as many ticks as the labels
  // leave room for at this size and font, their boxes never overlapping.
  // An empty plot has no range to number: its axes stay blank (no +-1e-9 ticks).
  plotting::AxisRoom x_room, y_room;
  x_room.length = right - left;
  x_room.label_length = [](const std::string& label, const void*) {
    return double(ImGui::CalcTextSize(translator().numbers(label).c_str()).x);
  };
  x_room.gap = 1.0 * font;
  y_room.length = bottom - top;
  y_room.label_length = [](const std::string& label, const void*) {
    return double(ImGui::CalcTextSize(translator().numbers(label).c_str()).y);
  };
  y_room.gap = 0.3 * font;
  const plotting::AxisTicks xt =
      has_data ? plotting::ticks_that_fit(xs.range(), xs.log, x_room) : plotting::AxisTicks{};
  const plotting::AxisTicks yt =
      has_data ? plotting::ticks_that_fit(ys.range(), ys.log, y_room) : plotting::AxisTicks{};
  for (std::size_t i = 0; i < xt.values.size(); ++i) {
    const float px = xs.pixel(xt.values[i]);
    if (px < left - 0.5f || px > right + 0.5f) continue;
    draw->AddLine(ImVec2(px, top), ImVec2(px, bottom), kGrid);
    draw->AddLine(ImVec2(px, bottom), ImVec2(px, bottom + 0.3f * font), kAxis);
    const std::string shown = translator().numbers(xt.labels[i]);
    const char* label = shown.c_str();
    const float w = ImGui::CalcTextSize(label).x;
    draw->AddText(ImVec2(px - 0.5f * w, bottom + 0.3f * font), kDimText, label);
  }
  for (std::size_t i = 0; i < yt.values.size(); ++i) {
    const float py = ys.pixel(yt.values[i]);
    if (py < top - 0.5f || py > bottom + 0.5f) continue;
    draw->AddLine(ImVec2(left, py), ImVec2(right, py), kGrid);
    draw->AddLine(ImVec2(left - 0.3f * font, py), ImVec2(left, py), kAxis);
    const std::string shown = translator().numbers(yt.labels[i]);
    const char* label = shown.c_str();
    const ImVec2 size = ImGui::CalcTextSize(label);
    draw->AddText(ImVec2(left - 0.4f * font - size.x, py - 0.5f * size.y), kDimText, label);
  }
  draw->AddLine(ImVec2(left, bottom), ImVec2(right, bottom), kAxis);
  draw->AddLine(ImVec2(left, top), ImVec2(left, bottom), kAxis);
  // A power of ten taken out of the tick labels is part of the axis label, as in the figures.
  auto axis_label = [&log_mark](const PlotAxis& axis, const std::string& scale_suffix) {
    return axis.label +
           (scale_suffix.empty() ? "" : "  " + scale_suffix) +
           (axis.log ? log_mark : "");
  };
  const std::string x_label = axis_label(spec.x, xt.scale_suffix);
  const float x_label_width = ImGui::CalcTextSize(x_label.c_str()).x;
  draw->AddText(ImVec2(0.5f * (left + right) - 0.5f * x_label_width, bottom + 1.25f * font), kText,
                x_label.c_str());
  const std::string y_label = axis_label(spec.y, yt.scale_suffix);
  draw->AddText(y_label_below ? ImVec2(origin.x + 0.5f * font, origin.y + 1.4f * font)
                              : ImVec2(std::max(left, origin.x + title_width + 1.5f * font),
                                       origin.y + 0.2f * font),
                kDimText, y_label.c_str());

  draw->PushClipRect(ImVec2(left, top - 1), ImVec2(right + 1, bottom + 1), true);
  if (!has_data) {
    // Wrapped to the frame: a phone's narrow plot must not cut the sentence off.
    const float wrap = std::max(right - left - font, 4 * font);
    const char* text =
        spec.empty_message.empty() ? tr("no data yet") : spec.empty_message.c_str();
    const ImVec2 size = ImGui::CalcTextSize(text, nullptr, false, wrap);
    draw->AddText(ImGui::GetFont(), ImGui::GetFontSize(),
                  ImVec2(0.5f * (left + right - size.x), 0.5f * (top + bottom - size.y)), kDimText,
                  text, nullptr, wrap);
  }
  // Series: lines thinned to at most two points per pixel column (min and max), so that
  // thousands of samples cost no more than the plot is wide.
  std::vector<ImVec2> line;
  for (const PlotSeries& s : spec.series) {
    const std::size_t n = std::min(s.x->size(), s.y->size());
    line.clear();
    float column = -1e9f, column_lo = 0, column_hi = 0, column_first = 0, column_last = 0;
    // The column's extremes in the order the curve meets them on its way through, so that a
    // steep stretch is drawn as one stroke, not a zigzag of up-down pairs.
    auto flush = [&] {
      if (column < -1e8f) return;
      const bool downward = column_last >= column_first;  // pixels grow downward
      line.push_back(ImVec2(column, downward ? column_lo : column_hi));
      if (column_hi != column_lo) line.push_back(ImVec2(column, downward ? column_hi : column_lo));
    };
    auto end_line = [&] {
      flush();
      if (line.size() >= 2)
        draw->AddPolyline(line.data(), int(line.size()), s.colour, 0, s.thickness);
      else if (line.size() == 1)
        draw->AddCircleFilled(line[0], 0.18f * font, s.colour);
      line.clear();
      column = -1e9f;
    };
    for (std::size_t i = 0; i < n; ++i) {
      const double xv = (*s.x)[i], yv = (*s.y)[i];
      if (!xs.usable(xv) || !ys.usable(yv)) {
        // A missing value (no wall hit in the interval) is a gap, not a straight line over it.
        if (!s.points && std::isnan(yv)) end_line();
        continue;
      }
      const float px = xs.pixel(xv), py = ys.pixel(yv);
      if (s.points) {
        if (px >= left - 4 && px <= right + 4)
          draw->AddCircleFilled(ImVec2(px, py), 0.22f * font, s.colour, 12);
        continue;
      }
      if (px < left - 2 * (right - left)) continue;
      if (std::floor(px) != column) {
        flush();
        column = std::floor(px);
        column_lo = column_hi = column_first = py;
      } else {
        column_lo = std::min(column_lo, py);
        column_hi = std::max(column_hi, py);
      }
      column_last = py;
    }
    end_line();
  }
  for (const PowerLawLine& f : spec.fits) {
    std::vector<ImVec2> curve;
    for (int k = 0; k <= 64; ++k) {
      const float px = left + (right - left) * float(k) / 64.0f;
      const double xv = xs.value(px), yv = f.prefactor * std::pow(xv, f.exponent);
      if (xs.usable(xv) && ys.usable(yv)) curve.push_back(ImVec2(px, ys.pixel(yv)));
    }
    if (curve.size() >= 2) draw->AddPolyline(curve.data(), int(curve.size()), f.colour, 0, 1.5f);
  }
  draw->PopClipRect();

  // Legend: left to right in the strip above the frame, wrapping as counted above.
  {
    float x = legend_left, y = legend_top;
    bool first = true;
    for (const LegendEntry& e : legend) {
      const float w = 2.0f * font + ImGui::CalcTextSize(e.label.c_str()).x + 0.8f * font;
      if (!first && x + w > legend_right) x = legend_left, y += 1.2f * font;
      first = false;
      const float mid = y + 0.5f * font;
      if (e.dashed)
        for (int k = 0; k < 3; ++k)
          draw->AddLine(ImVec2(x + k * 0.45f * font, mid),
                        ImVec2(x + 0.25f * font + k * 0.45f * font, mid), e.colour, 2.0f);
      else
        draw->AddLine(ImVec2(x, mid), ImVec2(x + 1.2f * font, mid), e.colour, 3.0f);
      draw->AddText(ImVec2(x + 1.6f * font, y), kText, e.label.c_str());
      x += w;
    }
  }

  // Hover: a cross-hair and, for each series, the point nearest in x.
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  if (hovered && has_data && mouse.x >= left && mouse.x <= right && mouse.y >= top &&
      mouse.y <= bottom) {
    draw->AddLine(ImVec2(mouse.x, top), ImVec2(mouse.x, bottom), colours.crosshair.packed());
    draw->AddLine(ImVec2(left, mouse.y), ImVec2(right, mouse.y), colours.crosshair.packed());
    const bool right_half = mouse.x > 0.5f * (left + right);
    ImGui::SetNextWindowPos(ImVec2(mouse.x + (right_half ? -1.5f : 1.5f) * font, origin.y),
                            ImGuiCond_Always, ImVec2(right_half ? 1.0f : 0.0f, 1.0f));
    ImGui::BeginTooltip();
    value_text("%s = %.5g", spec.x.label.c_str(), xs.value(mouse.x));
    value_text(tr("cursor: %s = %.5g"), spec.y.label.c_str(), ys.value(mouse.y));
    for (const PlotSeries& s : spec.series) {
      const std::size_t n = std::min(s.x->size(), s.y->size());
      float best = 1e30f;
      std::size_t best_i = n;
      for (std::size_t i = 0; i < n; ++i) {
        if (!xs.usable((*s.x)[i]) || !ys.usable((*s.y)[i])) continue;
        const float dx = xs.pixel((*s.x)[i]) - mouse.x;
        const float dy = s.points ? ys.pixel((*s.y)[i]) - mouse.y : 0.0f;
        const float d = dx * dx + dy * dy;
        if (d < best) best = d, best_i = i;
      }
      if (best_i == n) continue;
      const ImVec2 p(xs.pixel((*s.x)[best_i]), ys.pixel((*s.y)[best_i]));
      draw->AddCircle(p, 0.35f * font, s.colour, 16, 2.0f);
      // A swatch of the line's colour names the series; the text stays in the text colour,
      // since a faint line colour (the raw samples) is too pale for text.
      const ImVec2 at = ImGui::GetCursorScreenPos();
      ImGui::GetWindowDrawList()->AddLine(ImVec2(at.x, at.y + 0.5f * font),
                                          ImVec2(at.x + 1.2f * font, at.y + 0.5f * font), s.colour,
                                          3.0f);
      ImGui::Dummy(ImVec2(1.5f * font, font));
      ImGui::SameLine();
      value_text(tr("%s: %.5g at %.5g"), s.label.c_str(), (*s.y)[best_i], (*s.x)[best_i]);
    }
    ImGui::EndTooltip();
  }
  const ImVec2 corner(origin.x + width, origin.y + height);
  plot_export_menu(spec, origin, corner, right_clicked, state);
  plot_export_buttons(spec, origin, corner, state);
  ImGui::PopID();
  return hovered;
}

}  // namespace swarmlab
