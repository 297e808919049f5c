#include "ui/frame_demand.h"

#include <algorithm>
#include <chrono>

namespace swarmlab {

double steady_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double FrameDemand::seconds_to_next(double now) const {
  if (wanted(now)) return 0;
  if (editing_) return std::max(0.0, kCaretSeconds - (now - last_drawn_));
  return 1e9;
}

void FrameDemand::drawn(double now, bool moving, bool editing) {
  // What stopped by itself (a run at its end, a seek done) settles like a change from outside.
  if (moving_ && !moving)
    settle_ = kSettleFrames;
  else if (settle_ > 0)
    --settle_;
  moving_ = moving;
  editing_ = editing;
  last_drawn_ = now;
}

}  // namespace swarmlab
