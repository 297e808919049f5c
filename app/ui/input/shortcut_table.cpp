#include "ui/input/shortcut_table.h"

#include <SDL_scancode.h>

namespace swarmlab {
namespace {

/// Marks a text of the help window for the string tables (scripts/i18n.py finds tr("...")):
/// the table stays English, pure and free of the translator, and the help window passes each
/// text through the real tr() as it draws it (shortcuts.cpp).
constexpr const char* tr(const char* english) { return english; }

}  // namespace

const std::vector<Shortcut>& shortcut_table() {
  using A = ShortcutAction;
  constexpr ShiftKey any = ShiftKey::any;
  static const std::vector<Shortcut> table = {
      {SDL_SCANCODE_SPACE, false, any, tr("Space"),
       tr("play / pause (at the end: continue the run)"), A::play_pause, true},
      {SDL_SCANCODE_S, false, any, "S", tr("one step (pauses)"), A::step, false},
      {SDL_SCANCODE_R, false, any, "R", tr("reset to t = 0"), A::reset, true},
      {SDL_SCANCODE_EQUALS, false, any, "+", tr("twice as fast"), A::faster, true},
      {SDL_SCANCODE_KP_PLUS, false, any, nullptr, nullptr, A::faster, true},
      {SDL_SCANCODE_MINUS, false, any, "-", tr("half as fast"), A::slower, true},
      {SDL_SCANCODE_KP_MINUS, false, any, nullptr, nullptr, A::slower, true},
      {SDL_SCANCODE_C, false, any, "C", tr("colour by speed, mass, energy"), A::colour_by, true},
      {SDL_SCANCODE_G, false, any, "G", tr("springs: off, every pair, to the CM"), A::springs,
       true},
      {SDL_SCANCODE_T, false, any, "T", tr("trails on / off"), A::trails, true},
      {SDL_SCANCODE_O, false, any, "O", tr("orbit ahead of the selected particle"), A::orbit_ahead,
       true},
      {SDL_SCANCODE_K, false, any, "K", tr("container on / off (display)"), A::container, true},
      {SDL_SCANCODE_F, false, any, "F", tr("follow the centre of mass"), A::follow_cm, true},
      {SDL_SCANCODE_E, false, any, "E", tr("expand the container now"), A::expand_now, true},
      {SDL_SCANCODE_HOME, false, any, tr("Home"), tr("reframe the camera"), A::reframe, true},
      {SDL_SCANCODE_ESCAPE, false, any, tr("Esc"),
       tr("stop a fast-forward, else deselect the particle"), A::escape, true},
      // Time (time_controls.h): back and forth over the run so far, fast-forward.
      {SDL_SCANCODE_B, false, any, "B", tr("one step back"), A::step_back, true},
      {SDL_SCANCODE_LEFT, false, any, tr("Left / Right"), tr("back / on by 1/100 of a period"),
       A::back_coarse, true},
      {SDL_SCANCODE_RIGHT, false, any, nullptr, nullptr, A::forward_coarse, true},
      {SDL_SCANCODE_N, false, any, "N", tr("fast-forward to the end of this stage"),
       A::to_stage_end, true},
      {SDL_SCANCODE_END, false, any, tr("End"), tr("fast-forward to the end of the run"),
       A::to_run_end, true},
      {SDL_SCANCODE_1, false, any, "1", tr("show / hide the controls"), A::toggle_controls, true},
      {SDL_SCANCODE_2, false, any, "2", tr("show / hide the plots"), A::toggle_plots, true},
      // Regions as desktop apps switch them (F6); Ctrl+Tab is the browser's, never the app's.
      {SDL_SCANCODE_F6, false, ShiftKey::up, tr("F6, Ctrl+F6"),
       tr("keyboard: next region (menu, controls, transport, view, read-outs, timeline, plots)"),
       A::next_region, false},
      {SDL_SCANCODE_F6, true, any, nullptr, nullptr, A::next_region, false},
      {SDL_SCANCODE_F6, false, ShiftKey::down, tr("Shift+F6"), tr("keyboard: previous region"),
       A::previous_region, false},
      {SDL_SCANCODE_EQUALS, true, any, tr("Ctrl +"), tr("larger UI (projector)"), A::larger_ui,
       false},
      {SDL_SCANCODE_MINUS, true, any, tr("Ctrl -"), tr("smaller UI"), A::smaller_ui, false},
      {SDL_SCANCODE_F5, false, any, "F5",
       tr("presentation mode: light, large, the view and one plot"), A::presentation, true},
      {SDL_SCANCODE_F11, false, any, "F11", tr("fullscreen"), A::fullscreen, true},
      {SDL_SCANCODE_M, false, any, "M", tr("sound of the wall hits on / off"), A::sound, true},
      {SDL_SCANCODE_H, false, any, "H, F1", tr("this help"), A::help, true},
      {SDL_SCANCODE_F1, false, any, nullptr, nullptr, A::help, true},
  };
  return table;
}

std::optional<ShortcutAction> shortcut_for(int scancode, bool ctrl, bool shift) {
  for (const Shortcut& s : shortcut_table()) {
    const bool shift_fits = s.shift == ShiftKey::any || (s.shift == ShiftKey::down) == shift;
    if (s.scancode == scancode && s.ctrl == ctrl && shift_fits) return s.run;
  }
  return std::nullopt;
}

bool navigation_key(int scancode) {
  return scancode == SDL_SCANCODE_SPACE || scancode == SDL_SCANCODE_ESCAPE ||
         scancode == SDL_SCANCODE_HOME;
}

}  // namespace swarmlab
