// Dear ImGui's item hooks (IMGUI_ENABLE_TEST_ENGINE, as imgui_test_engine uses them) feeding
// the parallel DOM, and the value hook that imgui_hooks.cmake adds to the widgets whose state
// the stock hooks do not report. ImGui is built from Debian's sources with the hooks on the
// desktop and in the page alike (imgui_hooks.cmake).
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
