#include "ui/input/pointer_press.h"

#include <cmath>

namespace swarmlab {

PointerPress::Motion PointerPress::move_to(float x, float y) {
  const Motion m{x - last_x_, y - last_y_};
  last_x_ = x, last_y_ = y;
  travel_ += std::abs(m.dx) + std::abs(m.dy);
  return m;
}

}  // namespace swarmlab
