#include "ui/plots/plot_export.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <optional>
#include <utility>
#include <vector>

#include "i18n/translator.h"
#include "report/figure_csv.h"
#include "report/png_text.h"
#include "report/provenance.h"
#include "report/svg_plot.h"
#include "ui/kit/gl_api.h"
#include "ui/platform/save_dialog.h"
#include "ui/state/app_state.h"

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#include <stb_image_write.h>

namespace swarmlab {
namespace {

/// `format` (translated, with one %s) with the plot's title.
std::string with_title(const char* format, const std::string& title) {
  const int n = std::snprintf(nullptr, 0, format, title.c_str());
  std::string text(std::size_t(std::max(n, 0)) + 1, '\0');
  std::snprintf(text.data(), text.size(), format, title.c_str());
  text.pop_back();
  return text;
}

/// What made an export: this app, here and now, from the preset on screen's seed.
std::vector<std::string> made_by(const AppState& state) {
  return report::provenance_lines(report::provenance_now(report::seeds_of(state.preset)));
}

}  // namespace

void handle_plot_export(AppState& state) {
  std::optional<PlotExport> pending = std::exchange(state.plot_exports.asked, std::nullopt);
  if (!pending) return;
  const std::string stem =
      file_stem_of(state.preset.name) + "-" + file_stem_of(pending->file_title);
  pending->figure.made_by = made_by(state);
  SaveRequest r;
  switch (pending->kind) {
    case PlotExport::Kind::svg:
      r = {with_title(tr("the plot \u201c%s\u201d as SVG"), pending->title), stem + ".svg",
           report::svg_of(pending->figure), "image/svg+xml", false};
      break;
    case PlotExport::Kind::csv:
      r = {with_title(tr("the numbers of \u201c%s\u201d as CSV (panel,series,x,y)"),
                      pending->title),
           stem + ".csv", report::csv_of(pending->figure), "text/csv", false};
      break;
    case PlotExport::Kind::png:
      // The menu was drawn in this frame; the next one is drawn without it.
      state.plot_exports.png = std::move(pending);
      state.plot_exports.png_frames_to_wait = 1;
      return;
  }
  request_save(state, std::move(r));
}

void capture_plot_png(AppState& state) {
  std::optional<PlotExport>& png_capture = state.plot_exports.png;
  if (!png_capture) return;
  if (state.plot_exports.png_frames_to_wait-- > 0) return;
  const ImGuiIO& io = ImGui::GetIO();
  const float sx = io.DisplayFramebufferScale.x, sy = io.DisplayFramebufferScale.y;
  const int fb_height = int(io.DisplaySize.y * sy);
  const int x = int(png_capture->min_x * sx),
            w = int((png_capture->max_x - png_capture->min_x) * sx);
  const int h = int((png_capture->max_y - png_capture->min_y) * sy);
  const int y = fb_height - int(png_capture->max_y * sy);  // GL counts rows from the bottom
  std::vector<unsigned char> pixels(std::size_t(std::max(w, 0)) * std::size_t(std::max(h, 0)) * 4);
  std::string png;
  if (w > 0 && h > 0) {
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(x, y, w, h, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    png = png_of_gl_pixels(pixels.data(), w, h);
  }
  png = report::png_with_text(png, report::png_text_of(made_by(state)));
  const std::string stem =
      file_stem_of(state.preset.name) + "-" + file_stem_of(png_capture->file_title);
  const std::string title = png_capture->title;
  png_capture.reset();
  if (png.empty()) {
    state.status = tr("The plot could not be read from the screen for a PNG");
    state.status_is_error = true;
    return;
  }
  request_save(state, {with_title(tr("the plot \u201c%s\u201d as PNG (as on screen)"), title),
                       stem + ".png", std::move(png), "image/png", false});
}

std::string png_of_gl_pixels(const unsigned char* rgba, int width, int height) {
  std::string bytes;
  stbi_flip_vertically_on_write(1);  // OpenGL's first row is the bottom one
  stbi_write_png_to_func(
      [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                                   std::size_t(size));
      },
      &bytes, width, height, 4, rgba, 4 * width);
  return bytes;
}

}  // namespace swarmlab
