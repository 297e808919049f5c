#pragma once
// The keyboard's shortcuts as data: which key and modifiers do what, and how the help window
// names them. Pure (SDL's scancode names only, no ImGui, no AppState), so a test can hold the
// keys to the rule that browsers and screen readers keep theirs: nothing here takes Ctrl+Tab,
// Ctrl+W or Ctrl+L. shortcuts.cpp runs the actions and lists the table in the help window.

#include <optional>
#include <vector>

namespace swarmlab {

enum class ShortcutAction {
  play_pause, step, reset, faster, slower, colour_by, springs, trails, orbit_ahead, container,
  follow_cm, expand_now, reframe, escape, step_back, back_coarse, forward_coarse, to_stage_end,
  to_run_end, toggle_controls, toggle_plots, larger_ui, smaller_ui, presentation, fullscreen,
  sound, help, next_region, previous_region,
};

/// Whether Shift must be up, down, or does not matter ("+" is Shift+= on many layouts).
enum class ShiftKey { any, up, down };

struct Shortcut {
  int scancode;  ///< SDL scancode: ImGui 1.86's SDL backend indexes KeysDown by scancode
  bool ctrl;     ///< Ctrl must be down (true) or up (false)
  ShiftKey shift;
  const char* keys;    ///< as the help window lists them; null: a second key of the row above
  const char* action;  ///< what it does, for the help window
  ShortcutAction run;
  bool repeats;  ///< held down, it repeats (a step or a UI scale must not: a slow frame once
                 ///< turned one Ctrl - into two)
};

/// Every shortcut, in the help window's order.
const std::vector<Shortcut>& shortcut_table();

/// The shortcut a key pressed with these modifiers runs, if any (the first that matches).
std::optional<ShortcutAction> shortcut_for(int scancode, bool ctrl, bool shift);

/// Keys that keyboard navigation uses while its focus is shown: Space activates the focused
/// control, Escape backs out, Home scrolls. Shortcuts on them wait while the focus shows.
bool navigation_key(int scancode);

}  // namespace swarmlab
