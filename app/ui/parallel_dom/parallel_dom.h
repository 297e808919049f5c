// The parallel DOM's model: every item Dear ImGui drew in the last frame, in reading order,
// with its role, name, state and rectangle (mirrored_item.h), and what the page asked of them
// (activate, focus, type). Fed by ImGui's item hooks (imgui_item_hooks.cpp), read and asked
// by the page (web/js_parallel_dom.cpp, web/parallel_dom.js). One mechanism for every item:
// no panel registers its widgets; panels only add the text a screen reader should read
// (mirror_text) and tooltips (item_tooltip.h).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "ui/parallel_dom/mirrored_item.h"

struct ImGuiContext;

namespace swarmlab {

class ParallelDom {
 public:
  // Around one frame (app/ui/main_loop.cpp): the requests are applied before NewFrame, the
  // items collected while the frame is drawn and published after it.
  void apply_requests();
  void begin_frame();
  void end_frame();

  // ImGui's hooks, while an item is drawn (imgui_item_hooks.cpp).
  void item_added(ImGuiContext& g, unsigned id, float x0, float y0, float x1, float y1);
  void item_value(unsigned id, ValueKind kind, std::string_view value);
  void item_info(ImGuiContext& g, unsigned id, std::string_view label, bool checkable, bool checked,
                 bool openable, bool opened);
  /// The tooltip of the item last drawn (its description, or its name when the label is an icon).
  void item_tooltip(unsigned id, std::string_view tooltip);
  /// ImGui drew `text` at (x0, y0)-(x1, y1) (the size it needs) in the room (rx0, ry0)-(rx1, ry1)
  /// it could show in (third_party/imgui/patches/01-*): text wider than its room is cut off. It
  /// belongs to the item last added, or is plain text.
  void text_drawn(ImGuiContext& g, std::string_view text, float x0, float y0, float x1, float y1,
                  float rx0, float ry0, float rx1, float ry1);
  /// Whether an item out of sight still needs drawing once for its name (ImGui's clipping asks;
  /// third_party/imgui/patches/02-*): true once for an item not yet named, then false.
  bool unnamed(unsigned id);
  /// The item just drawn is a tab (a selectable of a wrapping tab strip, wrapping_tabs.h).
  void item_tab(unsigned id, bool selected);
  /// The name of an item that shows no label (item_tooltip.h, name_item).
  void item_name(unsigned id, std::string_view name);
  /// Text a screen reader reads in place (a lesson's heading, its step, a question, feedback).
  void text(ItemRole role, std::string_view text);

  /// The last complete frame's items, in reading order.
  const std::vector<MirroredItem>& items() const { return published_; }
  /// Plain text (no item's label) cut off in the last frame: its name is the text, its
  /// rectangle the one it needs, `cut` set.
  const std::vector<MirroredItem>& cut_text() const { return cut_text_published_; }
  /// The text field ImGui is editing (0 when none), and its text.
  unsigned editing_id() const { return editing_id_; }
  const std::string& editing_text() const { return editing_text_; }
  /// The item ImGui's keyboard navigation is on (0 when none or hidden).
  unsigned nav_id() const { return nav_id_; }

  // What the page asks, applied before the next frame.
  void request_activate(unsigned id);
  /// ring: draw ImGui's focus ring (the focus came from the keyboard; a finger's or a mouse's
  /// focus moves no ring).
  void request_focus(unsigned id, bool ring);
  /// Types `text` into the field `id` (replacing what it holds) and commits it: with Enter
  /// (as a person pressing Enter: a lesson's answer is checked) or by leaving the field.
  void request_text(unsigned id, std::string text, bool enter);

 private:
  struct Known {  // what is kept of an item between frames (a scrolled-out item reports no label)
    ItemFacts facts;
    std::string label, value, tooltip, name;
    bool disabled = false;
    bool drawn_for_name = false;
    std::uint64_t cut_frame = 0;  // the frame its label was last cut off in  // drawn once out of sight to learn its name (unnamed())
    unsigned window = 0;
    std::uint64_t seen_frame = 0;
  };
  struct Drawn {  // one item or text of the frame being drawn
    unsigned id = 0;  // 0: text
    ItemRole text_role = ItemRole::paragraph;
    std::string text;
    float x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // its rectangle
    float cx0 = 0, cy0 = 0, cx1 = 0, cy1 = 0;  // its window's clip rectangle
    unsigned window = 0, root = 0;
    int sequence = 0;
    bool sticks_out = false;  // wider than its window's visible part (no horizontal scrolling)
  };
  struct Typing {
    unsigned id = 0;
    std::string text;
    bool enter = false;
    int phase = 0;  // 0 none, 1 activated, 2 typed, 3 Enter down
    int waited = 0;
  };

  MirroredItem mirror(const Drawn& d) const;

  std::uint64_t frame_ = 0;
  int sequence_ = 0;
  std::vector<Drawn> drawn_;
  std::unordered_map<unsigned, Known> known_;
  std::vector<MirroredItem> published_;
  std::vector<Drawn> cut_text_;  // plain text cut off this frame (id: the item last added)
  std::vector<MirroredItem> cut_text_published_;
  unsigned editing_id_ = 0, nav_id_ = 0;
  std::string editing_text_;
  unsigned activate_ = 0, focus_ = 0;
  bool focus_ring_ = false;
  Typing typing_;
};

/// The one the hooks feed (ImGui's context is one per program too).
ParallelDom& parallel_dom();

/// Text a screen reader reads where it stands in the current window (see ParallelDom::text).
void mirror_text(ItemRole role, std::string_view text);

}  // namespace swarmlab
