// What the page mirrors of one item the ImGui front end drew this frame, or of one piece of
// text it showed: a real HTML element with a role, a name and a state, over the canvas where
// the item is drawn (web/parallel_dom.js). Pure data and rules, tested natively.
#pragma once

#include <string>
#include <string_view>

namespace swarmlab {

/// The ARIA role an item is mirrored with (web/README.md, "Parallel DOM").
enum class ItemRole {
  button,
  checkbox,
  radio,
  tab,
  menuitem,
  menuitemcheckbox,
  combobox,
  textbox,  // text typed as text
  number,   // a number field: a textbox with the phone's decimal keyboard
  slider,   // a slider: a value in a range, typed as a number
  option,   // an entry of a list
  heading,  // text: a lesson's or a window's heading
  paragraph,
};

/// What an item's value hook says it is (the calls added to Dear ImGui's widgets in
/// third_party/imgui/patches/01-parallel-dom-item-hooks.patch pass these numbers).
enum class ValueKind { none = 0, text = 1, number = 2, slider = 3, radio = 4, combo = 5, option = 6 };

/// What ImGui's hooks report of one item while it is drawn.
struct ItemFacts {
  std::string_view label;  // as passed to the widget, "##id" parts included
  ValueKind value_kind = ValueKind::none;
  bool checkable = false, checked = false;  // ImGuiItemStatusFlags_Checkable, _Checked
  bool openable = false, opened = false;    // ImGuiItemStatusFlags_Openable, _Opened
  bool in_menu = false;                     // in a menu bar or a menu popup
  bool is_tab = false, tab_selected = false;
  bool is_close_button = false;  // a window's own close button
};

struct MirroredItem {
  unsigned id = 0;  // ImGui's ID of the item; 0 for text
  ItemRole role = ItemRole::button;
  std::string name;         // the accessible name
  std::string description;  // the tooltip, where the item has one
  std::string value;        // what a field, slider or combo shows
  bool checked = false;     // checkbox, radio, menu check, selected tab or option
  bool openable = false;    // a menu, combo or section: it opens and closes
  bool expanded = false;    // open
  bool has_popup = false;   // opens a menu or a list
  bool disabled = false;
  bool clipped = false;  // scrolled out of its window: (x, y) is where it would be drawn
  /// Its text is cut off (wider than the room it is drawn in, or shortened with "..."), or it
  /// sticks out of its window's visible part sideways (parallel_dom.h, text_drawn).
  bool cut = false;
  float x = 0, y = 0, width = 0, height = 0;  // CSS pixels of the canvas
  std::string region;                         // the title of the window it is in
  /// In a popup (a menu, a combo's list): the page groups its entries as a menu or a listbox
  /// (ARIA's required parents), inside the item that opened it when there is one (popup_of).
  bool in_popup = false;
  unsigned popup_of = 0;
};

/// The name a screen reader says for a label: the part before "##" ("Play##transport" ->
/// "Play"), or the tooltip's first line when the label is empty or an icon (no letter or
/// digit: "◀◀" with tooltip "Left: back by 1/100 of a period" -> that line).
std::string accessible_name(std::string_view label, std::string_view tooltip = {});

/// The role an item is mirrored with, from what the hooks reported.
ItemRole role_of(const ItemFacts& facts);

/// The window title a user sees: "Controls###controls" -> "Controls".
std::string window_title(std::string_view window_name);

/// The ARIA role's name as HTML writes it ("menuitemcheckbox", "textbox", ...).
const char* role_name(ItemRole role);

}  // namespace swarmlab
