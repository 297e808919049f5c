#include "ui/panels/window_placement.h"

#include <imgui.h>

namespace swarmlab {

void place(const ScreenRect& r) {
  ImGui::SetNextWindowPos(ImVec2(r.x, r.y));
  ImGui::SetNextWindowSize(ImVec2(r.width, r.height));
}

void record_panel(AppState& s, const char* name) {
  const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
  s.layout.panels.push_back({name, {pos.x, pos.y, size.x, size.y}, ImGui::GetScrollY(), ImGui::GetScrollMaxY()});
}

float content_height() {
  return ImGui::GetCursorPosY() - ImGui::GetStyle().ItemSpacing.y +
         ImGui::GetStyle().WindowPadding.y;
}

}  // namespace swarmlab
