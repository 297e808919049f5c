#include "ui/parallel_dom/item_tooltip.h"

#include <imgui_internal.h>

#include <cstdarg>
#include <cstdio>

#include "ui/parallel_dom/parallel_dom.h"

namespace swarmlab {

void item_tooltip(const char* format, ...) {
  char text[1024];
  va_list args;
  va_start(args, format);
  std::vsnprintf(text, sizeof text, format, args);
  va_end(args);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text);
  parallel_dom().item_tooltip(ImGui::GetItemID(), text);
}

void describe_item(std::string_view description) {
  parallel_dom().item_tooltip(ImGui::GetItemID(), description);
}

void name_item(std::string_view name) { parallel_dom().item_name(ImGui::GetItemID(), name); }

}  // namespace swarmlab
