#include "ui/plots/plot_export_menu.h"

#include <iterator>

#include "i18n/translator.h"
#include "ui/kit/theme_style.h"
#include "ui/kit/touch_target.h"
#include "ui/parallel_dom/item_tooltip.h"
#include "ui/plots/plot_figure.h"
#include "ui/state/app_state.h"

namespace swarmlab {
namespace {

void request_plot_export(const PlotSpec& spec, PlotExport::Kind kind, ImVec2 min, ImVec2 max,
                         AppState& state) {
  PlotExport e;
  e.kind = kind;
  e.title = spec.title;
  e.file_title = spec.file_title.empty() ? spec.title : spec.file_title;
  e.min_x = min.x, e.min_y = min.y;
  e.max_x = max.x, e.max_y = max.y;
  // SVG and CSV from the plot's own numbers, in the colours on screen; PNG is read from the
  // screen (plot_export.h).
  if (kind != PlotExport::Kind::png) e.figure = figure_of(spec, palette(state.presentation.theme));
  state.plot_exports.asked = e;
}

}  // namespace

void plot_export_buttons(const PlotSpec& spec, ImVec2 min, ImVec2 max, AppState& state) {
  // Labelled buttons, so that touch, the keyboard and a screen reader reach them as any other
  // (the right-click menu was the only way once, and a finger has no right button).
  const struct {
    const char* label;
    PlotExport::Kind kind;
    const char* tip;
  } kButtons[] = {
      {tr_id("Export CSV"), PlotExport::Kind::csv,
       tr("Export CSV: this plot's numbers (panel,series,x,y)")},
      {tr_id("Export PNG"), PlotExport::Kind::png, tr("Export PNG: this plot as on screen")},
      {tr_id("Export SVG"), PlotExport::Kind::svg,
       tr("Export SVG: this plot as a drawing, in its colours")},
  };
  const ImGuiStyle& style = ImGui::GetStyle();
  float width = 0;
  for (const auto& b : kButtons)
    width += ImGui::CalcTextSize(b.label, nullptr, true).x + 2 * style.FramePadding.x +
             style.ItemSpacing.x;
  // Right-aligned under the plot, where a saved file is looked for; they wrap on a narrow one.
  const float room = ImGui::GetContentRegionAvail().x;
  if (width < room) ImGui::SetCursorPosX(ImGui::GetCursorPosX() + room - width + style.ItemSpacing.x);
  for (std::size_t i = 0; i < std::size(kButtons); ++i) {
    if (i > 0) same_line_if_fits(target_width(kButtons[i].label));
    if (ImGui::Button(kButtons[i].label))
      request_plot_export(spec, kButtons[i].kind, min, max, state);
    item_tooltip("%s", kButtons[i].tip);
  }
}

void plot_export_menu(const PlotSpec& spec, ImVec2 min, ImVec2 max, bool open, AppState& state) {
  if (open) ImGui::OpenPopup("plot menu");
  if (!ImGui::BeginPopup("plot menu")) return;
  ImGui::TextDisabled("%s", spec.title.c_str());
  const auto ask = [&](PlotExport::Kind kind) { request_plot_export(spec, kind, min, max, state); };
  if (ImGui::MenuItem(tr_id("Export SVG..."))) ask(PlotExport::Kind::svg);
  if (ImGui::MenuItem(tr_id("Export PNG..."))) ask(PlotExport::Kind::png);
  if (ImGui::MenuItem(tr_id("Export CSV..."))) ask(PlotExport::Kind::csv);
  ImGui::EndPopup();
}

}  // namespace swarmlab
