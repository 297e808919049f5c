#include "ui/parallel_dom/parallel_dom.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <cstdio>

#include "i18n/translator.h"

namespace swarmlab {
namespace {

constexpr int kFramesToWaitForAField = 3;  // an activated field is active on the next frame

bool is_menu_window(const ImGuiWindow* w) {
  return w->DC.NavLayerCurrent == ImGuiNavLayer_Menu || (w->Flags & ImGuiWindowFlags_ChildMenu);
}

// A key held for one frame, as a person presses it (ImGui 1.86 reads io.KeysDown each frame).
void set_key(ImGuiKey key, bool down) {
  ImGuiIO& io = ImGui::GetIO();
  const int index = io.KeyMap[key];
  if (index >= 0 && index < IM_ARRAYSIZE(io.KeysDown)) io.KeysDown[index] = down;
}

std::string text_of(const ImGuiInputTextState& s) {
  std::string text(std::size_t(s.CurLenW) * 4 + 1, '\0');
  const int bytes = ImTextStrToUtf8(text.data(), int(text.size()), s.TextW.Data, s.TextW.Data + s.CurLenW);
  text.resize(std::size_t(bytes));
  return text;
}

}  // namespace

ParallelDom& parallel_dom() {
  static ParallelDom dom;
  return dom;
}

void mirror_text(ItemRole role, std::string_view text) { parallel_dom().text(role, text); }

void ParallelDom::begin_frame() {
  ++frame_;
  sequence_ = 0;
  drawn_.clear();
  cut_text_.clear();
  if (GImGui) GImGui->TestEngineHookItems = true;
}

void ParallelDom::item_added(ImGuiContext& g, unsigned id, float x0, float y0, float x1, float y1) {
  const ImGuiWindow* w = g.CurrentWindow;
  if (!w || (w->Flags & ImGuiWindowFlags_Tooltip)) return;
  Drawn d;
  d.id = id;
  d.x0 = x0, d.y0 = y0, d.x1 = x1, d.y1 = y1;
  d.cx0 = w->ClipRect.Min.x, d.cy0 = w->ClipRect.Min.y;
  d.cx1 = w->ClipRect.Max.x, d.cy1 = w->ClipRect.Max.y;
  d.window = w->ID;
  d.root = w->RootWindow->ID;
  d.sequence = sequence_++;
  // Sideways only: there are no horizontal scrollbars, while scrolling hides items above and
  // below. The slack: a selectable's box reaches half the item spacing past what it shows
  // (ImGui's Selectable), and 1 px for rounding.
  const float slack = 1 + 0.5f * g.Style.ItemSpacing.x;
  d.sticks_out = (x1 > d.cx1 + slack || x0 < d.cx0 - slack) && y1 > d.cy0 && y0 < d.cy1;
  drawn_.push_back(d);
  Known& k = known_[id];
  k.window = w->ID;
  k.seen_frame = frame_;
}

void ParallelDom::item_value(unsigned id, ValueKind kind, std::string_view value) {
  Known& k = known_[id];
  k.facts.value_kind = kind;
  k.value.assign(value);
}

void ParallelDom::item_info(ImGuiContext& g, unsigned id, std::string_view label, bool checkable,
                            bool checked, bool openable, bool opened) {
  Known& k = known_[id];
  k.label.assign(label);
  ItemFacts& f = k.facts;
  f.checkable = checkable, f.checked = checked, f.openable = openable, f.opened = opened;
  const ImGuiWindow* w = g.CurrentWindow;
  f.in_menu = w && is_menu_window(w);
  f.is_close_button = label == "#CLOSE";
  f.is_tab = false;
  if (ImGuiTabBar* bar = g.CurrentTabBar)
    for (const ImGuiTabItem& tab : bar->Tabs)
      if (tab.ID == id) f.is_tab = true, f.tab_selected = bar->SelectedTabId == id;
  k.disabled = (g.LastItemData.InFlags & ImGuiItemFlags_Disabled) != 0;
}

void ParallelDom::item_tooltip(unsigned id, std::string_view tooltip) {
  if (id) known_[id].tooltip.assign(tooltip);
}

void ParallelDom::text_drawn(ImGuiContext& g, std::string_view text, float x0, float y0, float x1,
                             float y1, float rx0, float ry0, float rx1, float ry1) {
  const ImGuiWindow* w = g.CurrentWindow;
  if (!w || (w->Flags & ImGuiWindowFlags_Tooltip)) return;
  if (y1 <= ry0 || y0 >= ry1) return;         // scrolled out of sight: not cut, hidden
  if (x1 <= rx1 + 1 && x0 >= rx0 - 1) return;  // fits (1 px of slack for a glyph's overhang)
  const unsigned id = g.LastItemData.ID;
  const auto it = id ? known_.find(id) : known_.end();
  if (it != known_.end() && it->second.seen_frame == frame_) it->second.cut_frame = frame_;
  Drawn d;
  d.id = id;
  d.text.assign(text);
  d.x0 = x0, d.y0 = y0, d.x1 = x1, d.y1 = y1;
  d.cx0 = rx0, d.cy0 = ry0, d.cx1 = rx1, d.cy1 = ry1;
  d.window = w->ID;
  d.root = w->RootWindow->ID;
  cut_text_.push_back(std::move(d));
}

bool ParallelDom::unnamed(unsigned id) {
  const auto it = known_.find(id);
  if (it == known_.end()) return false;  // not an item this frame (ItemAdd registers it first)
  Known& k = it->second;
  if (!k.label.empty() || !k.tooltip.empty() || !k.name.empty() || k.drawn_for_name) return false;
  k.drawn_for_name = true;
  return true;
}

void ParallelDom::item_tab(unsigned id, bool selected) {
  if (!id) return;
  ItemFacts& f = known_[id].facts;
  f.value_kind = ValueKind::none;  // not a list's option
  f.is_tab = true, f.tab_selected = selected;
}

void ParallelDom::item_name(unsigned id, std::string_view name) {
  if (id) known_[id].name.assign(name);
}

void ParallelDom::text(ItemRole role, std::string_view text) {
  const ImGuiContext* g = GImGui;
  if (!g || !g->CurrentWindow || text.empty()) return;
  const ImGuiWindow* w = g->CurrentWindow;
  Drawn d;
  d.text_role = role;
  d.text.assign(text);
  d.x0 = w->DC.CursorPos.x, d.y0 = w->DC.CursorPos.y;
  d.x1 = w->ClipRect.Max.x, d.y1 = d.y0 + g->FontSize;
  d.cx0 = w->ClipRect.Min.x, d.cy0 = w->ClipRect.Min.y;
  d.cx1 = w->ClipRect.Max.x, d.cy1 = w->ClipRect.Max.y;
  d.window = w->ID;
  d.root = w->RootWindow->ID;
  d.sequence = sequence_++;
  drawn_.push_back(std::move(d));
}

MirroredItem ParallelDom::mirror(const Drawn& d) const {
  MirroredItem m;
  m.x = d.x0, m.y = d.y0, m.width = d.x1 - d.x0, m.height = d.y1 - d.y0;
  // Where it shows: its rectangle within its window's clip rectangle.
  const float x0 = std::max(d.x0, d.cx0), y0 = std::max(d.y0, d.cy0);
  const float x1 = std::min(d.x1, d.cx1), y1 = std::min(d.y1, d.cy1);
  if (x1 > x0 && y1 > y0)
    m.x = x0, m.y = y0, m.width = x1 - x0, m.height = y1 - y0;
  else
    m.clipped = true;
  if (const ImGuiWindow* root = ImGui::FindWindowByID(d.root)) {
    m.region = window_title(root->Name);
    if (m.region.empty() && (root->Flags & ImGuiWindowFlags_MenuBar)) m.region = tr("Menu bar");
  }
  if (d.id == 0) {
    m.role = d.text_role;
    m.name = d.text;
    return m;
  }
  m.id = d.id;
  const auto it = known_.find(d.id);
  if (it == known_.end()) return m;  // no name: not mirrored (see end_frame)
  const Known& k = it->second;
  m.cut = d.sticks_out || k.cut_frame == frame_;
  const ItemFacts& f = k.facts;
  m.role = role_of(f);
  m.disabled = k.disabled;
  if (f.is_close_button) {
    char name[400];
    std::snprintf(name, sizeof name, tr("Close %s"), m.region.c_str());
    m.name = name;
  } else if (!k.name.empty()) {
    m.name = k.name;
    m.description = k.tooltip;
  } else {
    m.name = accessible_name(k.label, k.tooltip);
    if (m.name == accessible_name(k.label)) m.description = k.tooltip;  // else the tooltip is the name
  }
  switch (m.role) {
    case ItemRole::radio:
    case ItemRole::option: m.checked = k.value == "1"; break;
    case ItemRole::tab: m.checked = f.tab_selected; break;
    case ItemRole::checkbox:
    case ItemRole::menuitemcheckbox: m.checked = f.checked; break;
    case ItemRole::textbox:
    case ItemRole::number:
    case ItemRole::slider:
    case ItemRole::combobox: m.value = k.value; break;
    default: break;
  }
  if (f.value_kind == ValueKind::option && f.in_menu) m.checked = k.value == "1";
  m.has_popup = f.openable && (f.in_menu || f.value_kind == ValueKind::combo);
  m.openable = f.openable;
  m.expanded = f.openable && f.opened;
  return m;
}

void ParallelDom::end_frame() {
  const ImGuiContext& g = *GImGui;
  // Keep what is known of items drawn this frame only.
  for (auto it = known_.begin(); it != known_.end();)
    it = it->second.seen_frame == frame_ ? std::next(it) : known_.erase(it);

  editing_id_ = 0;
  editing_text_.clear();
  if (g.ActiveId != 0 && g.InputTextState.ID == g.ActiveId) {
    editing_id_ = g.ActiveId;
    editing_text_ = text_of(g.InputTextState);
  }
  nav_id_ = g.NavDisableHighlight ? 0 : g.NavId;

  // Reading order: the windows from top to bottom (the menu bar first), each window's items
  // in the order they were drawn; a popup (a menu, a list) right after the item that opened it.
  struct Group {
    unsigned root = 0;
    float top = 0, left = 0;
    bool popup = false;
    unsigned opened_by = 0;
    std::vector<const Drawn*> drawn;
  };
  std::vector<Group> groups;
  for (const Drawn& d : drawn_) {
    if (d.id != 0) {
      const auto it = known_.find(d.id);
      if (it == known_.end() || (it->second.label.empty() && it->second.tooltip.empty() &&
                                 it->second.name.empty() && !it->second.facts.is_close_button))
        continue;  // an item with no name (a child window, a scrollbar): nothing to say
    }
    auto group = std::find_if(groups.begin(), groups.end(), [&](const Group& gr) { return gr.root == d.root; });
    if (group == groups.end()) {
      Group gr;
      gr.root = d.root;
      if (const ImGuiWindow* w = ImGui::FindWindowByID(d.root)) {
        gr.top = w->Pos.y, gr.left = w->Pos.x;
        gr.popup = (w->Flags & ImGuiWindowFlags_Popup) != 0;
        if (w->Flags & ImGuiWindowFlags_MenuBar) gr.top = -1;  // the main menu bar first
        for (const ImGuiPopupData& p : g.OpenPopupStack)
          if (p.Window == w) gr.opened_by = p.PopupId;  // a menu's popup has its item's ID
      }
      groups.push_back(gr);
      group = std::prev(groups.end());
    }
    group->drawn.push_back(&d);
  }
  std::stable_sort(groups.begin(), groups.end(), [](const Group& a, const Group& b) {
    if (a.popup != b.popup) return !a.popup;
    if (a.popup) return false;  // popups keep the order they were opened in
    return a.top != b.top ? a.top < b.top : a.left < b.left;
  });
  published_.clear();
  for (const Group& gr : groups) {
    std::vector<MirroredItem> items;
    for (const Drawn* d : gr.drawn) {
      items.push_back(mirror(*d));
      items.back().in_popup = gr.popup;
    }
    auto at = published_.end();
    if (gr.popup && gr.opened_by != 0) {
      // A menu's popup has its item's ID; a combo's is derived from the combo's (BeginCombo).
      const auto parent = std::find_if(published_.begin(), published_.end(), [&](const MirroredItem& m) {
        return m.id == gr.opened_by || (m.role == ItemRole::combobox &&
                                        ImHashStr("##ComboPopup", 0, m.id) == gr.opened_by);
      });
      if (parent != published_.end()) {
        for (MirroredItem& m : items) {
          m.region = parent->region;  // read as part of where it opened
          m.popup_of = parent->id;
        }
        at = std::next(parent);
      }
    }
    published_.insert(at, items.begin(), items.end());
  }
  // Cut text that is no mirrored item's label: plain text, a window's title, a table's cell.
  cut_text_published_.clear();
  for (const Drawn& d : cut_text_) {
    const auto it = d.id ? known_.find(d.id) : known_.end();
    const bool item_label = it != known_.end() && std::any_of(published_.begin(), published_.end(),
                                                              [&](const MirroredItem& m) { return m.id == d.id; });
    if (item_label) continue;  // reported as the item's `cut`
    MirroredItem m;
    m.role = ItemRole::paragraph;
    m.name = d.text;
    m.cut = true;
    m.x = d.x0, m.y = d.y0, m.width = d.x1 - d.x0, m.height = d.y1 - d.y0;
    if (const ImGuiWindow* root = ImGui::FindWindowByID(d.root)) m.region = window_title(root->Name);
    cut_text_published_.push_back(std::move(m));
  }
}

void ParallelDom::request_activate(unsigned id) { activate_ = id; }
void ParallelDom::request_focus(unsigned id, bool ring) {
  focus_ = id;
  focus_ring_ = ring;
}
void ParallelDom::request_text(unsigned id, std::string text, bool enter) {
  typing_ = Typing{id, std::move(text), enter, 1, 0};
}

void ParallelDom::apply_requests() {
  ImGuiContext& g = *GImGui;
  if (focus_ != 0) {
    const auto it = known_.find(focus_);
    if (it != known_.end())
      if (ImGuiWindow* w = ImGui::FindWindowByID(it->second.window)) {
        ImGui::FocusWindow(w);
        ImGui::SetFocusID(focus_, w);
        // ImGui draws its focus ring on the item for a keyboard's focus, none for a pointer's.
        g.NavDisableHighlight = !focus_ring_;
        if (focus_ring_) g.NavDisableMouseHover = true;
        for (const Drawn& d : drawn_)
          if (d.id == focus_) ImGui::ScrollToBringRectIntoView(w, ImRect(d.x0, d.y0, d.x1, d.y1));
      }
    focus_ = 0;
  }
  if (activate_ != 0) {
    ImGui::ActivateItem(activate_);
    activate_ = 0;
  }
  Typing& t = typing_;
  switch (t.phase) {
    case 1:  // ask ImGui to open the field for typing (its text selected, as a Tab into it does)
      if (g.ActiveId != t.id) {
        g.NavNextActivateId = t.id;
        g.NavNextActivateFlags = ImGuiActivateFlags_PreferInput;
      }
      t.phase = 2;
      break;
    case 2:  // the field is open: replace its text
      if (g.ActiveId == t.id && g.InputTextState.ID == t.id) {
        g.InputTextState.SelectAll();
        if (t.text.empty())
          set_key(ImGuiKey_Backspace, true);
        else
          ImGui::GetIO().AddInputCharactersUTF8(t.text.c_str());
        t.phase = 3;
      } else if (++t.waited > kFramesToWaitForAField) {
        t.phase = 0;  // the field is gone (its panel closed): nothing to type into
      }
      break;
    case 3:  // commit: Enter, or leave the field
      set_key(ImGuiKey_Backspace, false);
      if (t.enter) {
        set_key(ImGuiKey_Enter, true);
        t.phase = 4;
      } else {
        if (g.ActiveId == t.id) ImGui::ClearActiveID();
        t.phase = 0;
      }
      break;
    case 4:
      set_key(ImGuiKey_Enter, false);
      t.phase = 0;
      break;
    default: break;
  }
}

}  // namespace swarmlab
