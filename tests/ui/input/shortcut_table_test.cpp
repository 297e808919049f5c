#include "ui/input/shortcut_table.h"

#include <SDL_scancode.h>
#include <doctest/doctest.h>

#include <string>

using namespace swarmlab;

TEST_CASE("shortcut_table: F6 and Ctrl+F6 move to the next region, Shift+F6 to the previous") {
  CHECK(shortcut_for(SDL_SCANCODE_F6, false, false) == ShortcutAction::next_region);
  CHECK(shortcut_for(SDL_SCANCODE_F6, true, false) == ShortcutAction::next_region);
  CHECK(shortcut_for(SDL_SCANCODE_F6, false, true) == ShortcutAction::previous_region);
}

TEST_CASE("shortcut_table: no key that a browser or a screen reader keeps") {
  // Chrome and Firefox take Ctrl+Tab (next tab), Ctrl+W (close the tab), Ctrl+L (address bar).
  for (int key : {SDL_SCANCODE_TAB, SDL_SCANCODE_W, SDL_SCANCODE_L})
    for (bool shift : {false, true}) {
      CAPTURE(key);
      CHECK_FALSE(shortcut_for(key, true, shift).has_value());
    }
  for (const Shortcut& s : shortcut_table()) {
    CAPTURE(s.scancode);
    CHECK_FALSE((s.ctrl && (s.scancode == SDL_SCANCODE_TAB || s.scancode == SDL_SCANCODE_W ||
                            s.scancode == SDL_SCANCODE_L)));
  }
}

TEST_CASE("shortcut_table: '+' works with or without Shift, Ctrl + scales the UI instead") {
  CHECK(shortcut_for(SDL_SCANCODE_EQUALS, false, true) == ShortcutAction::faster);
  CHECK(shortcut_for(SDL_SCANCODE_EQUALS, false, false) == ShortcutAction::faster);
  CHECK(shortcut_for(SDL_SCANCODE_EQUALS, true, false) == ShortcutAction::larger_ui);
}

TEST_CASE("shortcut_table: each key and modifiers run one action, and the help names them") {
  const auto& table = shortcut_table();
  bool f6_listed = false, shift_f6_listed = false;
  for (std::size_t i = 0; i < table.size(); ++i) {
    const Shortcut& a = table[i];
    // A row without its own words is listed with the row above ("Left / Right", "H, F1").
    if (!a.keys) CHECK(i > 0);
    if (a.keys && std::string(a.keys).find("F6") == 0) f6_listed = true;
    if (a.keys && std::string(a.keys) == "Shift+F6") shift_f6_listed = true;
    for (std::size_t j = i + 1; j < table.size(); ++j) {
      const Shortcut& b = table[j];
      const bool shifts_overlap = a.shift == ShiftKey::any || b.shift == ShiftKey::any ||
                                  a.shift == b.shift;
      CAPTURE(i);
      CAPTURE(j);
      CHECK_FALSE((a.scancode == b.scancode && a.ctrl == b.ctrl && shifts_overlap));
    }
  }
  CHECK(f6_listed);
  CHECK(shift_f6_listed);
}
