#include "ui/parallel_dom/mirrored_item.h"

#include <cctype>

namespace swarmlab {
namespace {

std::string_view before_hashes(std::string_view label) {
  const auto hashes = label.find("##");
  return hashes == std::string_view::npos ? label : label.substr(0, hashes);
}

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

// An icon label ("◀|", "▶▶", "x" for remove) says nothing to a screen reader: no two ASCII
// letters or digits.
bool says_something(std::string_view text) {
  int alnum = 0;
  for (const char c : text) alnum += std::isalnum(static_cast<unsigned char>(c)) ? 1 : 0;
  return alnum >= 2;
}

}  // namespace

std::string accessible_name(std::string_view label, std::string_view tooltip) {
  const std::string_view visible = trimmed(before_hashes(label));
  if (says_something(visible) || tooltip.empty()) return std::string(visible);
  std::string_view line = tooltip.substr(0, tooltip.find('\n'));
  // Tooltips lead with the key: "B: one step back". The key is a shortcut, not the name.
  const auto colon = line.find(": ");
  if (colon != std::string_view::npos && colon <= 6) line.remove_prefix(colon + 2);
  return std::string(trimmed(line));
}

ItemRole role_of(const ItemFacts& f) {
  switch (f.value_kind) {
    case ValueKind::text: return ItemRole::textbox;
    case ValueKind::number: return ItemRole::number;
    case ValueKind::slider: return ItemRole::slider;
    case ValueKind::radio: return ItemRole::radio;
    case ValueKind::combo: return ItemRole::combobox;
    case ValueKind::option: return f.in_menu ? ItemRole::menuitem : ItemRole::option;
    case ValueKind::none: break;
  }
  if (f.is_close_button) return ItemRole::button;
  if (f.is_tab) return ItemRole::tab;
  if (f.in_menu) {
    // ImGui's MenuItem reports every entry as checkable; only a ticked one shows a check.
    if (f.checkable && f.checked) return ItemRole::menuitemcheckbox;
    return ItemRole::menuitem;
  }
  if (f.checkable) return ItemRole::checkbox;
  return ItemRole::button;
}

std::string window_title(std::string_view window_name) {
  return std::string(trimmed(before_hashes(window_name)));
}

const char* role_name(ItemRole role) {
  switch (role) {
    case ItemRole::button: return "button";
    case ItemRole::checkbox: return "checkbox";
    case ItemRole::radio: return "radio";
    case ItemRole::tab: return "tab";
    case ItemRole::menuitem: return "menuitem";
    case ItemRole::menuitemcheckbox: return "menuitemcheckbox";
    case ItemRole::combobox: return "combobox";
    case ItemRole::textbox: return "textbox";
    case ItemRole::number: return "textbox";
    case ItemRole::slider: return "slider";
    case ItemRole::option: return "option";
    case ItemRole::heading: return "heading";
    case ItemRole::paragraph: return "paragraph";
  }
  return "button";
}

}  // namespace swarmlab
