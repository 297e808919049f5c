#include "ui/plots/plot_export.h"
#include "ui/platform/save_dialog.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "ui/app_state.h"
#include "ui/platform/gl_api.h"

#include "report/figure_csv.h"
#include "report/svg_plot.h"

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#include <stb_image_write.h>

namespace swarmlab {
namespace {

std::optional<PlotExport> pending;      // asked for in the menu this frame
std::optional<PlotExport> png_capture;  // a PNG waiting for a frame without the menu
int png_frames_to_wait = 0;

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
      if (std::isfinite(x) && (!spec.x.log || x > 0)) x_lo = std::min(x_lo, x), x_hi = std::max(x_hi, x);
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

void handle_plot_export(AppState& state) {
  if (!pending) return;
  const std::string stem = file_stem_of(state.preset.name) + "-" + file_stem_of(pending->title);
  SaveRequest r;
  switch (pending->kind) {
    case PlotExport::Kind::svg:
      r = {"the plot \u201c" + pending->title + "\u201d as SVG", stem + ".svg",
           std::move(pending->content), "image/svg+xml", false};
      break;
    case PlotExport::Kind::csv:
      r = {"the numbers of \u201c" + pending->title + "\u201d as CSV (panel,series,x,y)",
           stem + ".csv", std::move(pending->content), "text/csv", false};
      break;
    case PlotExport::Kind::png:
      // The menu was drawn in this frame; the next one is drawn without it.
      png_capture = std::move(pending);
      png_frames_to_wait = 1;
      pending.reset();
      return;
  }
  pending.reset();
  request_save(state, std::move(r));
}

void capture_plot_png(AppState& state) {
  if (!png_capture) return;
  if (png_frames_to_wait-- > 0) return;
  const ImGuiIO& io = ImGui::GetIO();
  const float sx = io.DisplayFramebufferScale.x, sy = io.DisplayFramebufferScale.y;
  const int fb_height = int(io.DisplaySize.y * sy);
  const int x = int(png_capture->min.x * sx), w = int((png_capture->max.x - png_capture->min.x) * sx);
  const int h = int((png_capture->max.y - png_capture->min.y) * sy);
  const int y = fb_height - int(png_capture->max.y * sy);  // GL counts rows from the bottom
  std::vector<unsigned char> pixels(std::size_t(std::max(w, 0)) * std::size_t(std::max(h, 0)) * 4);
  std::string png;
  if (w > 0 && h > 0) {
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(x, y, w, h, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    png = png_of_gl_pixels(pixels.data(), w, h);
  }
  const std::string stem = file_stem_of(state.preset.name) + "-" + file_stem_of(png_capture->title);
  const std::string title = png_capture->title;
  png_capture.reset();
  if (png.empty()) {
    state.status = "The plot could not be read from the screen for a PNG";
    state.status_is_error = true;
    return;
  }
  request_save(state, {"the plot \u201c" + title + "\u201d as PNG (as on screen)", stem + ".png",
                       std::move(png), "image/png", false});
}

std::string png_of_gl_pixels(const unsigned char* rgba, int width, int height) {
  std::string bytes;
  stbi_flip_vertically_on_write(1);  // OpenGL's first row is the bottom one
  stbi_write_png_to_func(
      [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data), std::size_t(size));
      },
      &bytes, width, height, 4, rgba, 4 * width);
  return bytes;
}

}  // namespace swarmlab
