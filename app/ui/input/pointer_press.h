#pragma once
// One press of the mouse's button on the 3D view, followed from the place it went down: the
// drag turns the camera by the pointer's motion since the previous frame of this press, never
// since wherever the pointer was before it. A touchscreen or an interactive whiteboard acting
// as a mouse presses at a new place with no motion before, and ImGui's MouseDelta then spans
// the whole jump (finding 13 of issue 21: about 4 rad). Pure.

namespace swarmlab {

class PointerPress {
 public:
  /// A press travelling less than this (pixels, summed over its frames) is a click: it selects.
  static constexpr float kClickTravel = 4;

  struct Motion {
    float dx = 0, dy = 0;
  };

  /// The button went down at x, y.
  void start(float x, float y) { last_x_ = x, last_y_ = y, travel_ = 0; }
  /// The button is held with the pointer at x, y: the motion since the last frame of the press.
  Motion move_to(float x, float y);
  bool is_click() const { return travel_ < kClickTravel; }

 private:
  float last_x_ = 0, last_y_ = 0;
  float travel_ = 0;
};

}  // namespace swarmlab
