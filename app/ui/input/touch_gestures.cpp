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

void TouchGestures::down(long id, float x, float y, TouchSurface surface, double ms) {
  if (count_ == 2 || find(id)) return;  // a third finger changes nothing
  fingers_[count_++] = {id, x, y};
  if (count_ == 1) {
    start_x_ = x, start_y_ = y, start_ms_ = ms;
    switch (surface) {
      case TouchSurface::view:
        mode_ = Mode::view_pending;
        break;
      case TouchSurface::panel:
        mode_ = Mode::panel_pending;
        break;
      case TouchSurface::control:
        mode_ = Mode::press;
        mouse_.push_back({x, y, true});
        break;
    }
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

void TouchGestures::move(long id, float x, float y, double ms) {
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
      if (!far) break;
      if (ms - start_ms_ >= kHoldMs) {
        // Held still, then moved: press where it landed (what a slider grabs), then follow.
        mode_ = Mode::press;
        mouse_.push_back({start_x_, start_y_, true});
      } else {
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

void TouchGestures::up(long id, float x, float y, double /*ms*/) {
  Finger* f = find(id);
  if (!f) return;
  f->x = x, f->y = y;
  lift_x_ = x, lift_y_ = y;
  if (mode_ == Mode::view_pending) {
    pending_.tap = true, pending_.tap_x = x, pending_.tap_y = y;
  } else if (mode_ == Mode::panel_pending || mode_ == Mode::press) {
    // Held (or pressed) where the finger left, then released: a tap clicks, a drag ends there.
    const bool held_there =
        !mouse_.empty() && mouse_.back().down && mouse_.back().x == x && mouse_.back().y == y;
    if (!held_there) mouse_.push_back({x, y, true});
    mouse_.push_back({x, y, false});
  }
  *f = fingers_[--count_];  // the other finger (if any) takes slot 0
  // After a pinch the last finger neither orbits nor taps: the gesture ends with it.
  mode_ = count_ == 0 ? Mode::none : mode_ == Mode::two_finger ? Mode::view_done : mode_;
}

TouchFrame TouchGestures::frame() {
  TouchFrame out = pending_;
  pending_ = TouchFrame{};
  if (!mouse_.empty()) {
    const Mouse m = mouse_.front();
    mouse_.pop_front();
    out.pointer = true, out.x = m.x, out.y = m.y, out.down = m.down;
  } else if (count_ > 0 && (mode_ == Mode::scroll || mode_ == Mode::press)) {
    out.pointer = true, out.x = fingers_[0].x, out.y = fingers_[0].y;
    out.down = mode_ == Mode::press;
  } else if (out.scroll_y != 0) {
    // A flick that lifted before this frame still scrolls the window it was on.
    out.pointer = true, out.x = lift_x_, out.y = lift_y_;
  }
  return out;
}

}  // namespace swarmlab
