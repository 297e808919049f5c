#pragma once
// A move of the run in time under way: a seek or a fast-forward, carried out a frame's time
// budget at a time (time_controls.h starts and carries it on) so that the window never
// freezes. The app's state holds one, and a record of the last fast-forward.

#include <cstddef>
#include <vector>

namespace swarmlab {

/// A move of the run to a target step, under way over several frames. A seek of the window
/// (the timeline, step back) goes unseen; one asked for by the page (to_time, the JS API's
/// seek) and the fast-forwards show their progress.
struct TimeTravel {
  enum class Kind { none, seek, to_time, to_stage_end, to_run_end };
  Kind kind = Kind::none;
  long id = 0;      ///< which travel this is (AppState counts them): the page follows its seek
  long from = 0;    ///< the step it started from (after the jump to a snapshot)
  long target = 0;  ///< the step it goes to
  long chunk = 1;   ///< steps between looks at the clock, doubled or halved to fit the budget

  bool active() const { return kind != Kind::none; }
  /// How much of the way is done, 0 to 1.
  double progress(long step) const {
    return target == from ? 1.0 : double(step - from) / double(target - from);
  }
};

/// How a seek the page asked for (Kind::to_time) ended, kept until the page reads it.
struct TravelEnd {
  long id = 0;
  double t = 0;  ///< the run's time when it ended
  /// At its target; false: cancelled (a new seek, Play or Pause, Cancel or Esc, a new preset).
  bool reached = false;
};

/// The last fast-forward as its progress bar showed it, kept after it ends: what a test
/// (state().last_fast_forward) reads instead of catching a bar that may last a frame or two.
struct FastForwardRecord {
  static constexpr std::size_t kKept = 200;        ///< progress values kept (the first frames')
  TimeTravel::Kind kind = TimeTravel::Kind::none;  ///< none: no fast-forward yet
  int frames = 0;                                  ///< frames its progress bar was drawn
  std::vector<double> progress;  ///< the progress drawn, one a frame (the first kKept)
  bool reached = false;          ///< it got to its target (not cancelled or overtaken)
  double longest_ms = 0;         ///< the most one frame spent on it (ms of wall time)
};

}  // namespace swarmlab
