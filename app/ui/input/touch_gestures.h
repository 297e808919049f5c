#pragma once
// Fingers as on a PhET sim, told apart from a mouse: on the 3D view a tap selects (or, on empty
// space, deselects), one finger orbits, two fingers pinch to zoom and drag to pan; on a panel or
// any window over the view (the welcome, a menu, a popup) a drag scrolls it without pressing
// what the finger started on, a tap clicks, and a finger held still for a moment before it
// moves presses (to drag a slider); on a control that takes drags at once (the timeline's bar)
// the finger presses as it lands. Pure: a function of the finger events alone, each with its
// own time stamp (never the frame's time, so a slow frame cannot turn a drag into a press). The
// main loop feeds it SDL's finger events in window pixels and applies what frame() returns to
// ImGui's mouse and the camera.

#include <deque>

namespace swarmlab {

/// What is under a finger as it lands.
enum class TouchSurface {
  view,     ///< the 3D view, with no window over it
  panel,    ///< a panel or a window over the view: drags scroll, taps click
  control,  ///< a control dragged at once (the timeline's bar): pressed as the finger lands
};

/// What the fingers did since the last frame.
struct TouchFrame {
  // On the 3D view, in window pixels.
  float orbit_dx = 0, orbit_dy = 0;  ///< one finger dragged
  float zoom = 1;                    ///< two fingers: distance now / distance before
  float pan_dx = 0, pan_dy = 0;      ///< two fingers: their midpoint moved
  bool tap = false;                  ///< a tap on the view at tap_x, tap_y
  float tap_x = 0, tap_y = 0;
  // On a panel: ImGui's mouse for this frame, when `pointer`.
  bool pointer = false;  ///< a finger drives the mouse; else the mouse is nowhere
  float x = 0, y = 0;
  bool down = false;   ///< the left button
  float scroll_y = 0;  ///< pixels to scroll the panel under the finger (> 0: further down)
};

class TouchGestures {
 public:
  /// A finger moving less than this (pixels) is still a tap; held still this long
  /// (milliseconds, by its own events' times) on a panel before it moves, it presses.
  static constexpr float kSlop = 10;
  static constexpr double kHoldMs = 350;

  /// A finger touched at x, y over `surface`; ms: the event's own time stamp.
  void down(long id, float x, float y, TouchSurface surface, double ms);
  void move(long id, float x, float y, double ms);
  void up(long id, float x, float y, double ms);
  /// What happened since the last call; call once per frame.
  TouchFrame frame();
  /// Whether a finger is down or a press or click is still being delivered.
  bool active() const { return count_ > 0 || !mouse_.empty(); }
  int fingers() const { return count_; }  ///< fingers down now

 private:
  struct Finger {
    long id = -1;
    float x = 0, y = 0;
  };
  enum class Mode { none, view_pending, orbit, two_finger, view_done, panel_pending, scroll, press };
  /// ImGui's mouse on one frame: ImGui reads the button once a frame, so a press and its
  /// release (or a press and the last place it was dragged to) take a frame each.
  struct Mouse {
    float x = 0, y = 0;
    bool down = false;
  };

  Finger* find(long id);
  float spread() const;  ///< distance between the two fingers

  Finger fingers_[2];
  int count_ = 0;
  Mode mode_ = Mode::none;
  float start_x_ = 0, start_y_ = 0;  ///< where the first finger touched
  double start_ms_ = 0;
  float lift_x_ = 0, lift_y_ = 0;  ///< where a finger last left the glass
  float last_spread_ = 0, last_mid_x_ = 0, last_mid_y_ = 0;
  TouchFrame pending_;       ///< accumulated until frame()
  std::deque<Mouse> mouse_;  ///< frames of ImGui's mouse still to deliver, one per frame
};

}  // namespace swarmlab
