#include "ui/input/shortcuts.h"

#include "ui/time/time_controls.h"

#include <SDL.h>
#include <imgui.h>

#include <algorithm>

#include "ui/classroom/presentation.h"
#include "ui/classroom/theme_style.h"

namespace swarmlab {
namespace {

struct Shortcut {
  int scancode;  ///< SDL scancode: ImGui 1.86's SDL backend indexes KeysDown by scancode
  bool ctrl;
  const char* keys;
  const char* action;
  void (*run)(AppState&);
};

template <class E>
E next(E value, int count) {
  return E((int(value) + 1) % count);
}

const Shortcut kShortcuts[] = {
    {SDL_SCANCODE_SPACE, false, "Space", "play / pause (at the end: continue the run)",
     [](AppState& s) { play_or_continue(s); }},
    {SDL_SCANCODE_S, false, "S", "one step (pauses)",
     [](AppState& s) { s.step_once = true, s.playing = false; }},
    {SDL_SCANCODE_R, false, "R", "reset to t = 0", [](AppState& s) { s.restart(); }},
    {SDL_SCANCODE_EQUALS, false, "+", "twice as fast",
     [](AppState& s) { s.speed = std::min(s.speed * 2, 1e4); }},
    {SDL_SCANCODE_KP_PLUS, false, nullptr, nullptr,
     [](AppState& s) { s.speed = std::min(s.speed * 2, 1e4); }},
    {SDL_SCANCODE_MINUS, false, "-", "half as fast",
     [](AppState& s) { s.speed = std::max(s.speed / 2, 1e-3); }},
    {SDL_SCANCODE_KP_MINUS, false, nullptr, nullptr,
     [](AppState& s) { s.speed = std::max(s.speed / 2, 1e-3); }},
    {SDL_SCANCODE_C, false, "C", "colour by speed, mass, energy",
     [](AppState& s) {
       s.view.colour_by = next(s.view.colour_by, 3);
       s.colour_scale = ColourScale{};
     }},
    {SDL_SCANCODE_G, false, "G", "springs: off, every pair, to the CM",
     [](AppState& s) { s.view.springs = next(s.view.springs, 3); }},
    {SDL_SCANCODE_T, false, "T", "trails on / off", [](AppState& s) { s.view.trails ^= true; }},
    {SDL_SCANCODE_O, false, "O", "orbit ahead of the selected particle",
     [](AppState& s) { s.view.orbit ^= true; }},
    {SDL_SCANCODE_K, false, "K", "container on / off (display)",
     [](AppState& s) { s.view.container ^= true; }},
    {SDL_SCANCODE_F, false, "F", "follow the centre of mass",
     [](AppState& s) { s.view.follow_cm ^= true, s.reframe = true; }},
    {SDL_SCANCODE_E, false, "E", "expand the container now",
     [](AppState& s) {
       s.run->expand_container(s.preset.expansion ? s.preset.expansion->factor : 1.1);
     }},
    {SDL_SCANCODE_HOME, false, "Home", "reframe the camera", [](AppState& s) { s.reframe = true; }},
    {SDL_SCANCODE_ESCAPE, false, "Esc", "stop a fast-forward, else deselect the particle",
     [](AppState& s) {
       if (s.travel.active()) return cancel_travel(s);
       s.selected.reset();
       s.update_followed();
     }},
    // Time (time_controls.h): back and forth over the run so far, fast-forward.
    {SDL_SCANCODE_B, false, "B", "one step back", [](AppState& s) { step_back(s, false); }},
    {SDL_SCANCODE_LEFT, false, "Left / Right", "back / on by 1/100 of a period",
     [](AppState& s) { step_back(s, true); }},
    {SDL_SCANCODE_RIGHT, false, nullptr, nullptr, [](AppState& s) { step_forward_coarse(s); }},
    {SDL_SCANCODE_N, false, "N", "fast-forward to the end of this stage",
     [](AppState& s) { fast_forward_to_stage_end(s); }},
    {SDL_SCANCODE_END, false, "End", "fast-forward to the end of the run",
     [](AppState& s) { fast_forward_to_run_end(s); }},
    {SDL_SCANCODE_1, false, "1", "show / hide the controls",
     [](AppState& s) { s.layout.controls ^= true; }},
    {SDL_SCANCODE_2, false, "2", "show / hide the plots",
     [](AppState& s) { s.layout.plots ^= true; }},
    {SDL_SCANCODE_EQUALS, true, "Ctrl +", "larger UI (projector)",
     [](AppState& s) { s.layout.step_ui_scale(+1); }},
    {SDL_SCANCODE_MINUS, true, "Ctrl -", "smaller UI",
     [](AppState& s) { s.layout.step_ui_scale(-1); }},
    {SDL_SCANCODE_F5, false, "F5", "presentation mode: light, large, the view and one plot",
     [](AppState& s) { set_presentation(s, !s.presentation.on); }},
    {SDL_SCANCODE_F11, false, "F11", "fullscreen",
     [](AppState& s) { set_fullscreen(s, !s.presentation.fullscreen_wanted); }},
    {SDL_SCANCODE_M, false, "M", "sound of the wall hits on / off",
     [](AppState& s) { set_sound(s, !s.presentation.sound); }},
    {SDL_SCANCODE_H, false, "H, F1", "this help", [](AppState& s) { s.layout.help ^= true; }},
    {SDL_SCANCODE_F1, false, nullptr, nullptr, [](AppState& s) { s.layout.help ^= true; }},
};

}  // namespace

/// Keys that keyboard navigation uses while its focus is shown: Space activates the focused
/// control, Escape backs out, Home scrolls.
bool navigation_key(int scancode) {
  return scancode == SDL_SCANCODE_SPACE || scancode == SDL_SCANCODE_ESCAPE ||
         scancode == SDL_SCANCODE_HOME;
}

void handle_shortcuts(AppState& state) {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantTextInput) return;
  for (const Shortcut& s : kShortcuts)
    // No key repeat for a step or a UI scale: a slow frame once turned one Ctrl - into two.
    // While the keyboard-navigation focus shows, its keys (Space, Esc, ...) belong to it.
    if (s.ctrl == io.KeyCtrl && !(io.NavVisible && navigation_key(s.scancode)) &&
        ImGui::IsKeyPressed(s.scancode, !s.ctrl && s.scancode != SDL_SCANCODE_S))
      s.run(state);
}

void draw_help_window(AppState& state) {
  if (!state.layout.help) return;
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(viewport->Size.x * 0.5f, viewport->Size.y * 0.5f),
                          ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowBgAlpha(1.0f);
  if (!ImGui::Begin("Help: keys and mouse", &state.layout.help,
                    ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse)) {
    ImGui::End();
    return;
  }
  if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) {
    for (const Shortcut& s : kShortcuts) {
      if (!s.keys) continue;
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextColored(colour_vec4(current_palette().text_key), "%s", s.keys);
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(s.action);
    }
    const char* mouse[][2] = {{"drag", "orbit the camera"},
                              {"wheel", "zoom"},
                              {"right-drag", "slide the view (Home: back)"},
                              {"drag the timeline", "back or on to any time reached"},
                              {"click", "select a particle (trail, orbit ahead)"},
                              {"Ctrl+click", "type a value into a slider"},
                              {"hover", "equations behind the read-outs, values on the plots"},
                              {"arrows, Space", "keyboard: move to a control, press it"},
                              {"Ctrl+Tab, Alt", "keyboard: next window, the menu bar"}};
    for (const auto& m : mouse) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextColored(colour_vec4(current_palette().text_key), "%s", m[0]);
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(m[1]);
    }
    ImGui::EndTable();
  }
  // The welcome (what is on the screen, three things to try, the lessons) stays reachable.
  if (ImGui::Button("Welcome and lessons")) state.lessons.show_welcome = true;
  ImGui::End();
}

}  // namespace swarmlab
