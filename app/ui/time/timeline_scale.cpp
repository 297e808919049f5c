#include "ui/time/timeline_scale.h"

#include <algorithm>

namespace swarmlab {

float TimelineScale::x_of(long step) const {
  return x0 + float(double(step) / double(std::max(end, 1L))) * (x1 - x0);
}

long TimelineScale::step_at(float px) const {
  const double share = std::clamp(double(px - x0) / double(x1 - x0), 0.0, 1.0);
  return long(share * double(std::max(end, 1L)) + 0.5);
}

long TimelineScale::scrub_target(long wanted, bool pressed_now, long reached) {
  return pressed_now ? wanted : std::min(wanted, reached);
}

}  // namespace swarmlab
