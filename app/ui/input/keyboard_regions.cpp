#include "ui/input/keyboard_regions.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <array>

#include "i18n/translator.h"
#include "ui/input/region_cycle.h"

namespace swarmlab {
namespace {

/// The regions in reading order, by the window each is drawn in (ImGui's name of the main menu
/// bar, titles and the ids after ### in panels/panel_windows.cpp, panels/view_strips.cpp and
/// time/timeline_strip.cpp): the menu bar, the controls or the compact layout's drawer, the
/// transport bar, the 3D view (no window: there the keys go to the shortcuts), the read-outs,
/// the timeline, the plots.
/// The Controls and Plots windows are named with tr_id(), as panel_windows.cpp names them.
std::array<const char*, 8> regions() {
  return {"##MainMenuBar", tr_id("Controls"), "###drawer",   "###transport",
          nullptr,         "###readouts",     "###timeline", tr_id("Plots")};
}

ImGuiWindow* window_of(const char* region) {
  return region ? ImGui::FindWindowByName(region) : nullptr;
}

/// The region the keyboard is in: the one whose window holds ImGui's keyboard focus, the view
/// when no window does; none for a window outside the regions (a dialog, the help).
std::optional<std::size_t> current_region() {
  const ImGuiWindow* nav = GImGui->NavWindow ? GImGui->NavWindow->RootWindow : nullptr;
  const auto all = regions();
  for (std::size_t i = 0; i < all.size(); ++i)
    if (all[i] ? nav && nav == window_of(all[i]) : !nav) return i;
  return std::nullopt;
}

}  // namespace

void move_keyboard_region(int direction) {
  const auto all = regions();
  std::vector<bool> shown;
  for (const char* region : all) {
    const ImGuiWindow* w = window_of(region);
    shown.push_back(!region || (w && w->WasActive));  // drawn last frame
  }
  const std::optional<std::size_t> next = next_region(current_region(), shown, direction);
  if (!next) return;
  ImGuiContext& g = *GImGui;
  ImGui::ClearActiveID();
  ImGuiWindow* w = window_of(all[*next]);
  // As ImGui's own window switch does: focus the window, its first control if none was
  // focused there before, and show the focus ring.
  ImGui::FocusWindow(w);
  if (w && w->NavLastIds[0] == 0) ImGui::NavInitWindow(w, false);
  // A window of menus only (the menu bar) is entered on its menu layer, as ImGui does.
  if (w && w->DC.NavLayersActiveMaskNext == (1 << ImGuiNavLayer_Menu))
    g.NavLayer = ImGuiNavLayer_Menu;
  g.NavDisableHighlight = !w;
  g.NavDisableMouseHover = g.NavMousePosDirty = w != nullptr;
}

void keep_ctrl_tab_from_imgui() {
  ImGuiIO& io = ImGui::GetIO();
  if (io.KeyCtrl) io.KeysDown[io.KeyMap[ImGuiKey_Tab]] = false;
}

}  // namespace swarmlab
