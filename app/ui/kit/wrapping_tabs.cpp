#include "ui/kit/wrapping_tabs.h"

#include <imgui.h>
#include <imgui_internal.h>

#include "ui/kit/touch_target.h"
#include "ui/parallel_dom/parallel_dom.h"

namespace swarmlab {
namespace {

float tab_width(const char* label) {
  return ImGui::CalcTextSize(label, nullptr, true).x + 2 * ImGui::GetStyle().FramePadding.x;
}

}  // namespace

bool tabs_fit(const std::vector<const char*>& labels) {
  const ImGuiStyle& style = ImGui::GetStyle();
  float width = 0;
  for (const char* label : labels) width += tab_width(label) + style.ItemInnerSpacing.x;
  return width <= ImGui::GetContentRegionAvail().x;
}

int draw_wrapping_tabs(const std::vector<const char*>& labels, int selected) {
  int picked = selected;
  const float height = ImGui::GetFrameHeight();
  const ImGuiStyle& style = ImGui::GetStyle();
  ImGui::PushStyleVar(ImGuiStyleVar_SelectableTextAlign, ImVec2(0.5f, 0.5f));
  ImGui::PushStyleColor(ImGuiCol_Header, style.Colors[ImGuiCol_TabActive]);
  ImGui::PushStyleColor(ImGuiCol_HeaderHovered, style.Colors[ImGuiCol_TabHovered]);
  ImGui::PushStyleColor(ImGuiCol_HeaderActive, style.Colors[ImGuiCol_TabActive]);
  for (int i = 0; i < int(labels.size()); ++i) {
    const float width = tab_width(labels[i]);
    if (i > 0) same_line_if_fits(width);
    // An unselected tab is drawn as ImGui draws one: on the tab colour.
    const ImVec2 at = ImGui::GetCursorScreenPos();
    if (i != selected)
      ImGui::GetWindowDrawList()->AddRectFilled(at, ImVec2(at.x + width, at.y + height),
                                                ImGui::GetColorU32(ImGuiCol_Tab), style.TabRounding);
    if (ImGui::Selectable(labels[i], i == selected, 0, ImVec2(width, height))) picked = i;
    parallel_dom().item_tab(ImGui::GetItemID(), i == selected);
  }
  ImGui::PopStyleColor(3);
  ImGui::PopStyleVar();
  ImGui::Separator();
  return picked;
}

}  // namespace swarmlab
