#include <imgui.h>

#include <algorithm>
#include <cstring>

#include "i18n/translator.h"
#include "ui/lesson_player/lesson_panel.h"
#include "ui/panels/panels.h"
#include "ui/panels/window_placement.h"
#include "ui/panels/windows.h"

namespace swarmlab {
namespace {

/// The English a tr_id() label keeps as its ID ("Controles###Controls" -> "Controls"): the
/// name swarmlab.state() reports, whatever the language.
const char* english_of(const char* label) {
  const char* id = std::strstr(label, "###");
  return id ? id + 3 : label;
}

/// The controls, section by section (the wide layout's left panel, the drawer's first tab).
void draw_controls(AppState& s) {
  auto section = [&](const char* title, bool open_first, void (*body)(AppState&)) {
    ImGui::SetNextItemOpen(open_first, ImGuiCond_Once);
    if (ImGui::CollapsingHeader(title)) {
      ImGui::PushID(english_of(title));
      body(s);
      ImGui::PopID();
      ImGui::Spacing();
    }
  };
  section(tr_id("Scenario"), true, draw_scenario_panel);
  section(tr_id("System"), true, draw_system_panel);
  section(tr_id("Container"), bool(s.preset.container_radius), draw_container_panel);
  section(tr_id("Gravity, floor, drag"), s.preset.gravity || s.preset.floor || s.preset.drag,
          draw_forces_panel);
  section(tr_id("Walls and spheres"),
          !s.preset.wall_moves.empty() || s.preset.wall_temperature || s.preset.sphere_radius,
          draw_walls_panel);
  section(tr_id("Simulation"), true, draw_simulation_panel);
  section(tr_id("View"), false, draw_view_panel);
}

/// A finger dragging on the current window scrolls it (ImGui's own mouse-wheel routing was
/// seen to drop a scroll after a pinch, so the window under the finger is scrolled here).
void touch_scroll(const TouchFrame& t) {
  // Only the frontmost window under the finger: not a panel under the welcome or a menu.
  if (!t.pointer || t.scroll_y == 0 || !ImGui::IsWindowHovered()) return;
  ImGui::SetScrollY(std::clamp(ImGui::GetScrollY() + t.scroll_y, 0.0f, ImGui::GetScrollMaxY()));
}

}  // namespace

void draw_panel_windows(AppState& state, const ScreenLayout& layout, const TouchFrame& touch,
                        LessonTabStep* lesson_tab_step) {
  AppState& s = state;
  const ScreenLayout& l = layout;
  const ImGuiWindowFlags panel = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                 ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings;
  if (l.controls.shown() && s.layout.controls) {
    place(l.controls);
    if (ImGui::Begin(tr_id("Controls"), &s.layout.controls, panel)) {
      touch_scroll(touch);
      // The lesson at the top, its text box, task and buttons within 60% of the panel.
      if (s.lessons.open_lesson() &&
          ImGui::CollapsingHeader(tr_id("Lesson"), ImGuiTreeNodeFlags_DefaultOpen))
        draw_lesson(s, 0.6f * l.controls.height);
      draw_controls(s);
    }
    record_panel(s, "Controls");
    ImGui::End();
  } else if (l.controls.shown()) {
    // The controls are closed (presentation mode closes them) but a lesson is open: its column
    // shows the lesson alone (app.cpp keeps the column while a lesson is open).
    place(l.controls);
    if (ImGui::Begin(tr_id("Lesson"), nullptr, panel)) {
      touch_scroll(touch);
      draw_lesson(s, ImGui::GetContentRegionAvail().y);
    }
    record_panel(s, "Lesson");
    ImGui::End();
  }
  if (l.plots.shown()) {
    place(l.plots);
    if (ImGui::Begin(tr_id("Plots"), &s.layout.plots, panel)) {
      touch_scroll(touch);
      draw_instruments(s);
      draw_plots_panel(s);
    }
    record_panel(s, "Plots");
    ImGui::End();
  }
  if (l.drawer.shown()) {
    // Compact: one drawer beside or under the view, its parts as tabs, each scrolling alone.
    place(l.drawer);
    if (ImGui::Begin(tr_id("Panels###drawer"), nullptr, panel | ImGuiWindowFlags_NoTitleBar)) {
      if (ImGui::BeginTabBar("drawer", ImGuiTabBarFlags_FittingPolicyScroll)) {
        auto tab = [&](const char* name, bool shown, void (*body)(AppState&)) {
          // `name` is a tr_id() label: the child and the record keep its English.
          if (!shown || !ImGui::BeginTabItem(name)) return;
          if (ImGui::BeginChild(english_of(name))) {
            touch_scroll(touch);
            body(s);
          }
          record_panel(s, english_of(name));
          ImGui::EndChild();
          ImGui::EndTabItem();
        };
        // A lesson that opens or moves to another step brings its tab to the front.
        const std::pair<const Lesson*, std::size_t> step{s.lessons.open_lesson(), s.lessons.step()};
        const ImGuiTabItemFlags lesson_flags =
            step.first && step != *lesson_tab_step ? ImGuiTabItemFlags_SetSelected : 0;
        *lesson_tab_step = step;
        if (step.first && ImGui::BeginTabItem(tr_id("Lesson"), nullptr, lesson_flags)) {
          if (ImGui::BeginChild("Lesson")) {
            touch_scroll(touch);
            draw_lesson(s, ImGui::GetContentRegionAvail().y);
          }
          record_panel(s, "Lesson");
          ImGui::EndChild();
          ImGui::EndTabItem();
        }
        tab(tr_id("Controls"), s.layout.controls, draw_controls);
        tab(tr_id("Plots"), s.layout.plots, draw_plots_panel);
        tab(tr_id("Read-outs"), true, draw_readouts);
        tab(tr_id("Instruments"), true, draw_instruments);
        ImGui::EndTabBar();
      }
    }
    ImGui::End();
  }

}

}  // namespace swarmlab
