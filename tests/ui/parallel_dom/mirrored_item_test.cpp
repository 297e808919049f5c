// The parallel DOM's names and roles (app/ui/parallel_dom/mirrored_item.cpp): what a screen
// reader says for each kind of item ImGui draws.
#include "ui/parallel_dom/mirrored_item.h"

#include <doctest/doctest.h>

using namespace swarmlab;

TEST_CASE("accessible_name: the visible label, without its ## id") {
  CHECK(accessible_name("Play##transport") == "Play");
  CHECK(accessible_name("Copy link") == "Copy link");
  CHECK(accessible_name("  Check  ") == "Check");
  CHECK(accessible_name("Controls###controls") == "Controls");
  CHECK(accessible_name("##hidden") == "");
}

TEST_CASE("accessible_name: an icon is named by its tooltip's first line, without the key") {
  CHECK(accessible_name("\u25c0\u25c0", "Left: back by 1/100 of a period") == "back by 1/100 of a period");
  CHECK(accessible_name("\u25c0|", "B: one step back\nsecond line") == "one step back");
  CHECK(accessible_name("x", "Remove particle 3") == "Remove particle 3");
  CHECK(accessible_name("##speed", "Simulated time per second of real time") ==
        "Simulated time per second of real time");
  // A label that says something keeps it; the tooltip is then a description, not the name.
  CHECK(accessible_name("Reset", "R: back to t = 0") == "Reset");
  // An icon without a tooltip keeps what it shows: there is nothing better to say.
  CHECK(accessible_name("\u25b6\u25b6") == "\u25b6\u25b6");
}

TEST_CASE("role_of: each kind of ImGui item") {
  ItemFacts f;
  CHECK(role_of(f) == ItemRole::button);
  f.checkable = true;
  CHECK(role_of(f) == ItemRole::checkbox);
  f.in_menu = true;
  CHECK(role_of(f) == ItemRole::menuitem);  // MenuItem reports every entry as checkable
  f.checked = true;
  CHECK(role_of(f) == ItemRole::menuitemcheckbox);

  ItemFacts menu;
  menu.in_menu = true, menu.openable = true;
  CHECK(role_of(menu) == ItemRole::menuitem);

  ItemFacts tab;
  tab.is_tab = true;
  CHECK(role_of(tab) == ItemRole::tab);

  ItemFacts close;
  close.is_close_button = true, close.label = "#CLOSE";
  CHECK(role_of(close) == ItemRole::button);

  const std::pair<ValueKind, ItemRole> by_value[] = {
      {ValueKind::text, ItemRole::textbox},  {ValueKind::number, ItemRole::number},
      {ValueKind::slider, ItemRole::slider}, {ValueKind::radio, ItemRole::radio},
      {ValueKind::combo, ItemRole::combobox}, {ValueKind::option, ItemRole::option}};
  for (const auto& [kind, role] : by_value) {
    ItemFacts v;
    v.value_kind = kind;
    CHECK(role_of(v) == role);
  }
  ItemFacts entry;
  entry.value_kind = ValueKind::option, entry.in_menu = true;
  CHECK(role_of(entry) == ItemRole::menuitem);  // a Selectable in a menu is a menu entry
}

TEST_CASE("window_title and role_name") {
  CHECK(window_title("Plots###plots") == "Plots");
  CHECK(window_title("##MainMenuBar") == "");
  CHECK(std::string(role_name(ItemRole::number)) == "textbox");  // with inputmode=decimal
  CHECK(std::string(role_name(ItemRole::menuitemcheckbox)) == "menuitemcheckbox");
  CHECK(std::string(role_name(ItemRole::slider)) == "slider");
}
