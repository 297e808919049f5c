#include <imgui.h>

#include <algorithm>
#include <string>

#include "i18n/language.h"
#include "i18n/translator.h"
#include "ui/classroom/presentation.h"
#include "ui/lesson_player/lesson_panel.h"
#include "ui/panels/windows.h"
#include "ui/platform/save_dialog.h"

namespace swarmlab {
namespace {

/// View > Language: each language under its own name, the one in use ticked. The switch
/// happens between frames (the main loop), since it may need other glyphs.
void draw_language_menu(AppState& s) {
  if (!ImGui::BeginMenu(tr_id("Language"))) return;
  for (const Language& l : languages())
    if (ImGui::MenuItem(l.native_name.c_str(), nullptr, s.language.code == l.code) &&
        s.language.code != l.code)
      s.language.pending = l.code;
  ImGui::EndMenu();
}

/// Records where the menu whose title began at x0 lies in the bar: up to the next title.
void record_menu(AppState& s, const char* name, float x0) {
  const float x1 = ImGui::GetCursorScreenPos().x - ImGui::GetStyle().ItemSpacing.x;
  s.layout.menus.push_back(
      {name, {x0, ImGui::GetWindowPos().y, x1 - x0, ImGui::GetWindowSize().y}, 0});
}

}  // namespace

float draw_menu_bar(AppState& state) {
  AppState& s = state;
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  const float font = ImGui::GetFontSize();
  float height = 0;
  s.layout.menus.clear();
  if (ImGui::BeginMainMenuBar()) {
    float x0 = ImGui::GetCursorScreenPos().x;
    // Where the bar is too short for every title (a phone, a longer language), Help goes
    // into the View menu rather than off the screen's edge.
    float titles = x0;
    for (const char* title : {tr_id("Scenario"), tr_id("View"), tr_id("Lessons"), tr_id("Help")})
      titles += ImGui::CalcTextSize(title, nullptr, true).x + 2 * ImGui::GetStyle().ItemSpacing.x;
    const bool help_in_view = titles > viewport->Pos.x + viewport->Size.x;
    if (ImGui::BeginMenu(tr_id("Scenario"))) {
      for (const ShippedPreset& p : s.shipped)
        if (ImGui::MenuItem(tr_id(p.preset.name.empty() ? p.id.c_str() : p.preset.name.c_str()),
                            nullptr, s.shipped_id == p.id)) {
          s.open(p.preset, "my-" + p.id);
          s.shipped_id = p.id;
        }
      ImGui::Separator();
      if (ImGui::MenuItem(tr_id("Save preset..."))) request_save_preset(s);
      if (ImGui::MenuItem(tr_id("Export samples as CSV..."))) request_samples_csv(s);
      if (ImGui::MenuItem(tr_id("Export stages as CSV..."), nullptr, false,
                          !s.run->primary().stages().empty()))
        request_stages_csv(s);
      ImGui::Separator();
      if (ImGui::MenuItem(tr_id("Quit"))) request_quit(s);
      ImGui::EndMenu();
    }
    record_menu(s, "Scenario", x0);
    x0 = ImGui::GetCursorScreenPos().x;
    if (ImGui::BeginMenu(tr_id("View"))) {
      ImGui::MenuItem(tr_id("Controls"), "1", &s.layout.controls);
      ImGui::MenuItem(tr_id("Plots"), "2", &s.layout.plots);
      if (ImGui::MenuItem(tr_id("Larger UI"), "Ctrl +")) s.layout.step_ui_scale(+1);
      if (ImGui::MenuItem(tr_id("Smaller UI"), "Ctrl -")) s.layout.step_ui_scale(-1);
      // The layout follows the window unless the user picks one.
      if (ImGui::BeginMenu(tr_id("Layout"))) {
        const char* labels[] = {tr_noop("Automatic (from the window size)"),
                                tr_noop("Wide: side panels"),
                                tr_noop("Compact: view first, panels in a drawer")};
        for (LayoutMode m : {LayoutMode::automatic, LayoutMode::wide, LayoutMode::compact})
          if (ImGui::MenuItem(tr_id(labels[int(m)]), nullptr, s.layout.mode == m)) s.layout.mode = m;
        ImGui::EndMenu();
      }
      draw_presentation_menu_items(s);
      draw_language_menu(s);
      if (help_in_view) {
        ImGui::Separator();
        if (ImGui::MenuItem(tr_id("Help"))) s.layout.help = !s.layout.help;
      }
      ImGui::EndMenu();
    }
    record_menu(s, "View", x0);
    x0 = ImGui::GetCursorScreenPos().x;
    draw_lessons_menu(s);
    record_menu(s, "Lessons", x0);
    if (!help_in_view && ImGui::MenuItem(tr_id("Help"))) s.layout.help = !s.layout.help;
    const std::string title = std::string("Swarm Lab  \u2014  ") + tr(s.preset.name.c_str());
    const float w = ImGui::CalcTextSize(title.c_str()).x;
    // On a narrow screen the title would run into the menus: the page says what runs.
    if (ImGui::GetCursorPosX() + font + w < viewport->Size.x) {
      ImGui::SameLine(std::max(ImGui::GetCursorPosX() + font, 0.5f * (viewport->Size.x - w)));
      ImGui::TextDisabled("%s", title.c_str());
    }
    height = ImGui::GetWindowSize().y;
    ImGui::EndMainMenuBar();
  }

  return height;
}

}  // namespace swarmlab
