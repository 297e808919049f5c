#pragma once
// Fingers as on a PhET sim, told apart from a mouse: on the 3D view a tap selects (or, on empty
// space, deselects), one finger orbits, two fingers pinch to zoom and drag to pan; on a panel a
// drag scrolls it without pressing what the finger started on, a tap clicks, and a finger held
// still for a moment presses (to drag a slider). Pure: the main loop feeds it SDL's finger
// events in window pixels and applies what frame() returns to ImGui's mouse and the camera.

#include <optional>

namespace swarmlab {

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
  /// A finger moving less than this (pixels) is still a tap; held still this long (seconds)
  /// on a panel, it presses.
  static constexpr float kSlop = 10;
  static constexpr double kHoldSeconds = 0.35;

  /// A finger touched at x, y; on_view: over the 3D view (else over a panel). now in seconds.
  void down(long id, float x, float y, bool on_view, double now);
  void move(long id, float x, float y);
  void up(long id, float x, float y);
  /// What happened since the last call; call once per frame.
  TouchFrame frame(double now);
  /// Whether a finger is down or a tap's click is still being delivered.
  bool active() const { return count_ > 0 || click_ > 0; }
  int fingers() const { return count_; }  ///< fingers down now

 private:
  struct Finger {
    long id = -1;
    float x = 0, y = 0;
  };
  enum class Mode { none, view_pending, orbit, two_finger, view_done, panel_pending, scroll, press };

  Finger* find(long id);
  float spread() const;  ///< distance between the two fingers

  Finger fingers_[2];
  int count_ = 0;
  Mode mode_ = Mode::none;
  float start_x_ = 0, start_y_ = 0;  ///< where the first finger touched
  double start_time_ = 0;
  float last_spread_ = 0, last_mid_x_ = 0, last_mid_y_ = 0;
  TouchFrame pending_;  ///< accumulated until frame()
  /// A tap on a panel becomes a click over frames: 2 press, 1 release, 0 done (a held press
  /// ends with 1).
  int click_ = 0;
  float click_x_ = 0, click_y_ = 0;
};

}  // namespace swarmlab
