// Dear ImGui's item hooks (IMGUI_ENABLE_TEST_ENGINE, as imgui_test_engine uses them) feeding
// the parallel DOM, and the value hook that third_party/imgui/patches add to the widgets whose
// state the stock hooks do not report. ImGui is built from Debian's sources with the hooks on,
// on the desktop and in the page alike (third_party/imgui/README.md).
#include <imgui.h>
#include <imgui_internal.h>

#include "ui/parallel_dom/parallel_dom.h"

void ImGuiTestEngineHook_ItemAdd(ImGuiContext* ctx, const ImRect& bb, ImGuiID id) {
  swarmlab::parallel_dom().item_added(*ctx, id, bb.Min.x, bb.Min.y, bb.Max.x, bb.Max.y);
}

void ImGuiTestEngineHook_ItemInfo(ImGuiContext* ctx, ImGuiID id, const char* label,
                                  ImGuiItemStatusFlags flags) {
  swarmlab::parallel_dom().item_info(*ctx, id, label ? label : "",
                                     flags & ImGuiItemStatusFlags_Checkable,
                                     flags & ImGuiItemStatusFlags_Checked,
                                     flags & ImGuiItemStatusFlags_Openable,
                                     flags & ImGuiItemStatusFlags_Opened);
}

void ImGuiTestEngineHook_Log(ImGuiContext*, const char*, ...) {}

const char* ImGuiTestEngine_FindItemDebugLabel(ImGuiContext*, ImGuiID) { return nullptr; }

void ParallelDomHook_ItemValue(ImGuiContext*, ImGuiID id, int kind, const char* value) {
  swarmlab::parallel_dom().item_value(id, static_cast<swarmlab::ValueKind>(kind), value ? value : "");
}

bool ParallelDomHook_Unnamed(ImGuiID id) { return swarmlab::parallel_dom().unnamed(id); }

void ParallelDomHook_TextDrawn(ImGuiContext* ctx, ImDrawList* draw_list, ImVec2 pos, ImVec2 size,
                               const char* text, const char* text_end, const ImVec4* clip) {
  // The room the text is drawn in: the draw list's clip rectangle (its window's, or its table
  // cell's), within the explicit one if given, within the screen.
  ImVec4 room = draw_list->_CmdHeader.ClipRect;
  if (clip) {
    room.x = ImMax(room.x, clip->x), room.y = ImMax(room.y, clip->y);
    room.z = ImMin(room.z, clip->z), room.w = ImMin(room.w, clip->w);
  }
  room.x = ImMax(room.x, 0.0f), room.z = ImMin(room.z, ctx->IO.DisplaySize.x);
  swarmlab::parallel_dom().text_drawn(*ctx, std::string_view(text, std::size_t(text_end - text)), pos.x,
                                      pos.y, pos.x + size.x, pos.y + size.y, room.x, room.y, room.z,
                                      room.w);
}
