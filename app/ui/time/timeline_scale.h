#pragma once
// Where a step of the run sits on the timeline's bar and which step lies under the pointer:
// one linear scale from the bar's left edge (step 0) to its right edge (the run's last step),
// so a drag puts the run exactly at the time under the pointer. Pure.

namespace swarmlab {

struct TimelineScale {
  float x0 = 0, x1 = 1;  ///< the bar's left and right edges, window pixels
  long end = 1;          ///< the run's last step, at x1

  float x_of(long step) const;
  /// The step under pixel px, nearest, within 0..end.
  long step_at(float px) const;
  /// Where a scrub goes with the pointer over `wanted`: anywhere on a press (beyond the time
  /// computed, it computes up to there), within the time computed while dragging.
  static long scrub_target(long wanted, bool pressed_now, long reached);
};

}  // namespace swarmlab
