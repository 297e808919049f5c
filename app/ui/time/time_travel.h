#pragma once
// A move of the run in time under way: a seek or a fast-forward, carried out a frame's time
// budget at a time (time_controls.h starts and carries it on) so that the window never
// freezes. The app's state holds one.

namespace swarmlab {

/// A move of the run to a target step, under way over several frames.
struct TimeTravel {
  enum class Kind { none, seek, to_stage_end, to_run_end };
  Kind kind = Kind::none;
  long from = 0;    ///< the step it started from (after the jump to a snapshot)
  long target = 0;  ///< the step it goes to
  long chunk = 1;   ///< steps between looks at the clock, doubled or halved to fit the budget

  bool active() const { return kind != Kind::none; }
  /// How much of the way is done, 0 to 1.
  double progress(long step) const {
    return target == from ? 1.0 : double(step - from) / double(target - from);
  }
};

}  // namespace swarmlab
