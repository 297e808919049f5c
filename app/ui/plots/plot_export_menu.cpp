#include "ui/parallel_dom/item_tooltip.h"
#include "ui/plots/plot_export_menu.h"

#include <iterator>
#include <utility>

#include "i18n/translator.h"
#include "ui/kit/theme_style.h"
#include "ui/kit/touch_target.h"
#include "ui/plots/plot_figure.h"

namespace swarmlab {
namespace {

std::optional<PlotExport> pending;  // asked for by a button or the menu, not yet taken by the app

void request_plot_export(const PlotSpec& spec, PlotExport::Kind kind, ImVec2 min, ImVec2 max) {
  PlotExport e;
  e.kind = kind;
  e.title = spec.title;
  e.file_title = spec.file_title.empty() ? spec.title : spec.file_title;
  e.min = min;
  e.max = max;
  // SVG and CSV from the plot's own numbers, in the colours on screen; PNG is read from the
  // screen (plot_export.h).
  if (kind != PlotExport::Kind::png) e.figure = figure_of(spec, current_palette());
  pending = e;
}

}  // namespace

void plot_export_buttons(const PlotSpec& spec, ImVec2 min, ImVec2 max) {
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
    if (ImGui::Button(kButtons[i].label)) request_plot_export(spec, kButtons[i].kind, min, max);
    item_tooltip("%s", kButtons[i].tip);
  }
}

void plot_export_menu(const PlotSpec& spec, ImVec2 min, ImVec2 max, bool open) {
  if (open) ImGui::OpenPopup("plot menu");
  if (!ImGui::BeginPopup("plot menu")) return;
  ImGui::TextDisabled("%s", spec.title.c_str());
  if (ImGui::MenuItem(tr_id("Export SVG..."))) request_plot_export(spec, PlotExport::Kind::svg, min, max);
  if (ImGui::MenuItem(tr_id("Export PNG..."))) request_plot_export(spec, PlotExport::Kind::png, min, max);
  if (ImGui::MenuItem(tr_id("Export CSV..."))) request_plot_export(spec, PlotExport::Kind::csv, min, max);
  ImGui::EndPopup();
}

std::optional<PlotExport> take_plot_export() { return std::exchange(pending, std::nullopt); }

}  // namespace swarmlab
