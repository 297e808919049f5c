#include <imgui.h>

#include <algorithm>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "i18n/translator.h"
#include "ui/kit/wrapping_tabs.h"
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

/// A panel's lines of text wrap at its right edge rather than run past it (a translation's
/// are longer); where it fits, a line shows as before. Tables keep their cells unwrapped
/// (readouts.cpp, particle_card.cpp, system_panel.cpp).
struct WrapAtEdge {
  WrapAtEdge() { ImGui::PushTextWrapPos(0); }
  ~WrapAtEdge() { ImGui::PopTextWrapPos(); }
  WrapAtEdge(const WrapAtEdge&) = delete;
  WrapAtEdge& operator=(const WrapAtEdge&) = delete;
};

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
      WrapAtEdge wrap;
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
      WrapAtEdge wrap;
      draw_lesson(s, ImGui::GetContentRegionAvail().y);
    }
    record_panel(s, "Lesson");
    ImGui::End();
  }
  if (l.plots.shown()) {
    place(l.plots);
    if (ImGui::Begin(tr_id("Plots"), &s.layout.plots, panel)) {
      touch_scroll(touch);
      WrapAtEdge wrap;
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
      // The drawer's parts: the lesson (while one is open), then the panels shown.
      struct Part {
        const char* label;  // a tr_id() label: the child and the record keep its English
        void (*body)(AppState&);
      };
      std::vector<Part> parts;
      const std::pair<const Lesson*, std::size_t> step{s.lessons.open_lesson(), s.lessons.step()};
      if (step.first) parts.push_back({tr_id("Lesson"), nullptr});
      if (s.layout.controls) parts.push_back({tr_id("Controls"), draw_controls});
      if (s.layout.plots) parts.push_back({tr_id("Plots"), draw_plots_panel});
      parts.push_back({tr_id("Read-outs"), draw_readouts});
      parts.push_back({tr_id("Instruments"), draw_instruments});
      // A lesson that opens or moves to another step brings its tab to the front.
      const bool lesson_to_front = step.first && step != *lesson_tab_step;
      *lesson_tab_step = step;
      std::string& open_part = s.layout.drawer_open;
      if (lesson_to_front) open_part = "Lesson";
      auto body = [&](const Part& part) {
        const char* name = english_of(part.label);
        open_part = name;
        if (ImGui::BeginChild(name)) {
          touch_scroll(touch);
          WrapAtEdge wrap;
          if (part.body)
            part.body(s);
          else
            draw_lesson(s, ImGui::GetContentRegionAvail().y);
        }
        record_panel(s, name);
        ImGui::EndChild();
      };
      std::vector<const char*> labels;
      for (const Part& part : parts) labels.push_back(part.label);
      // Where the tabs do not fit in one row they wrap onto more (wrapping_tabs.h).
      bool& wrapped_last = s.layout.drawer_tabs_wrapped;
      if (!tabs_fit(labels)) {
        int open = 0;
        for (int i = 0; i < int(parts.size()); ++i)
          if (open_part == english_of(parts[std::size_t(i)].label)) open = i;
        body(parts[std::size_t(draw_wrapping_tabs(labels, open))]);
        wrapped_last = true;
      } else if (ImGui::BeginTabBar("drawer", ImGuiTabBarFlags_FittingPolicyScroll)) {
        for (const Part& part : parts) {
          const char* name = english_of(part.label);
          const bool to_front = (lesson_to_front && std::strcmp(name, "Lesson") == 0) ||
                                (wrapped_last && open_part == name);
          if (!ImGui::BeginTabItem(part.label, nullptr, to_front ? ImGuiTabItemFlags_SetSelected : 0))
            continue;
          body(part);
          ImGui::EndTabItem();
        }
        wrapped_last = false;
        ImGui::EndTabBar();
      }
    }
    ImGui::End();
  }

}

}  // namespace swarmlab
