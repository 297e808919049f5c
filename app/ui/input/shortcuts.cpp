#include "ui/input/shortcuts.h"

#include "ui/time/time_controls.h"

#include <imgui.h>

#include <algorithm>

#include "i18n/translator.h"
#include "ui/classroom/presentation.h"
#include "ui/input/keyboard_regions.h"
#include "ui/input/shortcut_table.h"
#include "ui/kit/theme_style.h"

namespace swarmlab {
namespace {

template <class E>
E next(E value, int count) {
  return E((int(value) + 1) % count);
}

void run(ShortcutAction action, AppState& s) {
  using A = ShortcutAction;
  switch (action) {
    case A::play_pause: return play_or_continue(s);
    case A::step: s.step_once = true, s.playing = false; return;
    case A::reset: return s.restart();
    case A::faster: s.speed = std::min(s.speed * 2, 1e4); return;
    case A::slower: s.speed = std::max(s.speed / 2, 1e-3); return;
    case A::colour_by:
      s.view.colour_by = next(s.view.colour_by, 3);
      s.colour_scale = ColourScale{};
      return;
    case A::springs: s.view.springs = next(s.view.springs, 3); return;
    case A::trails: s.view.trails ^= true; return;
    case A::orbit_ahead: s.view.orbit ^= true; return;
    case A::container: s.view.container ^= true; return;
    case A::follow_cm: s.view.follow_cm ^= true, s.reframe = true; return;
    case A::expand_now:
      return s.run->expand_container(s.preset.expansion ? s.preset.expansion->factor : 1.1);
    case A::reframe: s.reframe = true; return;
    case A::escape:
      if (s.travel.active()) return cancel_travel(s);
      s.selected.reset();
      return s.update_followed();
    case A::step_back: return step_back(s, false);
    case A::back_coarse: return step_back(s, true);
    case A::forward_coarse: return step_forward_coarse(s);
    case A::to_stage_end: return fast_forward_to_stage_end(s);
    case A::to_run_end: return fast_forward_to_run_end(s);
    case A::toggle_controls: s.layout.controls ^= true; return;
    case A::toggle_plots: s.layout.plots ^= true; return;
    case A::larger_ui: return s.layout.step_ui_scale(+1);
    case A::smaller_ui: return s.layout.step_ui_scale(-1);
    case A::presentation: return set_presentation(s, !s.presentation.on);
    case A::fullscreen: return set_fullscreen(s, !s.presentation.fullscreen_wanted);
    case A::sound: return set_sound(s, !s.presentation.sound);
    case A::help: s.layout.help ^= true; return;
    case A::next_region: return move_keyboard_region(+1);
    case A::previous_region: return move_keyboard_region(-1);
  }
}

}  // namespace

void handle_shortcuts(AppState& state) {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantTextInput) return;
  for (const Shortcut& s : shortcut_table()) {
    const bool shift_fits = s.shift == ShiftKey::any || (s.shift == ShiftKey::down) == io.KeyShift;
    // While the keyboard-navigation focus shows, its keys (Space, Esc, ...) belong to it.
    if (s.ctrl == io.KeyCtrl && shift_fits && !(io.NavVisible && navigation_key(s.scancode)) &&
        ImGui::IsKeyPressed(s.scancode, s.repeats))
      run(s.run, state);
  }
}

void draw_help_window(AppState& state) {
  if (!state.layout.help) return;
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(viewport->Size.x * 0.5f, viewport->Size.y * 0.5f),
                          ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowBgAlpha(1.0f);
  if (!ImGui::Begin(tr_id("Help: keys and mouse"), &state.layout.help,
                    ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse)) {
    ImGui::End();
    return;
  }
  if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) {
    for (const Shortcut& s : shortcut_table()) {
      if (!s.keys) continue;
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      // The table is English (shortcut_table.cpp marks its texts for the string tables).
      ImGui::TextColored(colour_vec4(palette(state.presentation.theme).text_key), "%s", tr(s.keys));
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(tr(s.action));
    }
    const char* mouse[][2] = {
        {tr("drag"), tr("orbit the camera")},
        {tr("wheel"), tr("zoom")},
        {tr("right-drag"), tr("slide the view (Home: back)")},
        {tr("drag the timeline"), tr("back or on to any time reached")},
        {tr("click"), tr("select a particle (trail, orbit ahead)")},
        {tr("Ctrl+click"), tr("type a value into a slider")},
        {tr("hover"), tr("equations behind the read-outs, values on the plots")},
        {tr("arrows, Space"), tr("keyboard: move to a control, press it")}};
    for (const auto& m : mouse) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextColored(colour_vec4(palette(state.presentation.theme).text_key), "%s", m[0]);
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(m[1]);
    }
    ImGui::EndTable();
  }
  // The welcome (what is on the screen, three things to try, the lessons) stays reachable.
  // Embedded in a course page there is no welcome (it speaks of the menus).
  if (!state.embedded && ImGui::Button(tr_id("Welcome and lessons")))
    state.lessons.show_welcome = true;
  ImGui::End();
}

}  // namespace swarmlab
