#include "ui/input/touch_gestures.h"

#include <cmath>

namespace swarmlab {

TouchGestures::Finger* TouchGestures::find(long id) {
  for (int i = 0; i < count_; ++i)
    if (fingers_[i].id == id) return &fingers_[i];
  return nullptr;
}

float TouchGestures::spread() const {
  return std::hypot(fingers_[1].x - fingers_[0].x, fingers_[1].y - fingers_[0].y);
}

void TouchGestures::down(long id, float x, float y, bool on_view, double now) {
  if (count_ == 2 || find(id)) return;  // a third finger changes nothing
  fingers_[count_++] = {id, x, y};
  if (count_ == 1) {
    mode_ = on_view ? Mode::view_pending : Mode::panel_pending;
    start_x_ = x, start_y_ = y, start_time_ = now;
    return;
  }
  // A second finger on the view starts a pinch; on a panel it is ignored.
  if (mode_ == Mode::view_pending || mode_ == Mode::orbit || mode_ == Mode::view_done) {
    mode_ = Mode::two_finger;
    last_spread_ = spread();
    last_mid_x_ = 0.5f * (fingers_[0].x + fingers_[1].x);
    last_mid_y_ = 0.5f * (fingers_[0].y + fingers_[1].y);
  }
}

void TouchGestures::move(long id, float x, float y) {
  Finger* f = find(id);
  if (!f) return;
  const float dx = x - f->x, dy = y - f->y;
  f->x = x, f->y = y;
  const bool far = std::hypot(x - start_x_, y - start_y_) > kSlop;
  switch (mode_) {
    case Mode::view_pending:
      if (far) mode_ = Mode::orbit;
      break;
    case Mode::orbit:
      pending_.orbit_dx += dx, pending_.orbit_dy += dy;
      break;
    case Mode::two_finger: {
      const float s = spread();
      if (last_spread_ > 1 && s > 1) pending_.zoom *= s / last_spread_;
      last_spread_ = s;
      const float mx = 0.5f * (fingers_[0].x + fingers_[1].x);
      const float my = 0.5f * (fingers_[0].y + fingers_[1].y);
      pending_.pan_dx += mx - last_mid_x_, pending_.pan_dy += my - last_mid_y_;
      last_mid_x_ = mx, last_mid_y_ = my;
      break;
    }
    case Mode::panel_pending:
      if (far) {
        mode_ = Mode::scroll;
        pending_.scroll_y += start_y_ - y;  // the content follows the finger
      }
      break;
    case Mode::scroll:
      pending_.scroll_y -= dy;
      break;
    default:
      break;
  }
}

void TouchGestures::up(long id, float x, float y) {
  Finger* f = find(id);
  if (!f) return;
  f->x = x, f->y = y;
  if (mode_ == Mode::view_pending) {
    pending_.tap = true, pending_.tap_x = x, pending_.tap_y = y;
  } else if (mode_ == Mode::panel_pending) {
    click_ = 2, click_x_ = x, click_y_ = y;
  } else if (mode_ == Mode::press) {
    click_ = 1, click_x_ = x, click_y_ = y;  // released where the finger left
  }
  *f = fingers_[--count_];  // the other finger (if any) takes slot 0
  // After a pinch the last finger neither orbits nor taps: the gesture ends with it.
  mode_ = count_ == 0 ? Mode::none : mode_ == Mode::two_finger ? Mode::view_done : mode_;
}

TouchFrame TouchGestures::frame(double now) {
  if (mode_ == Mode::panel_pending && now - start_time_ >= kHoldSeconds) mode_ = Mode::press;
  TouchFrame out = pending_;
  pending_ = TouchFrame{};
  if (click_ > 0) {
    // Pressed on one frame, released on the next: ImGui reads the button once a frame.
    out.pointer = true, out.x = click_x_, out.y = click_y_, out.down = click_ == 2;
    --click_;
  } else if (count_ > 0 && (mode_ == Mode::scroll || mode_ == Mode::press)) {
    out.pointer = true, out.x = fingers_[0].x, out.y = fingers_[0].y;
    out.down = mode_ == Mode::press;
  }
  return out;
}

}  // namespace swarmlab
