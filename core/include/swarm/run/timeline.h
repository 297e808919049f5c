#pragma once
/// A run that can be moved to any step it has reached, back or forward, landing on the same
/// state, samples and stages to the last bit as the first pass did.
///
/// The engines are deterministic, so a state is recomputed rather than stored: the timeline
/// keeps snapshots (whole clones of the runs, engines included: the fast engine's orbits,
/// anchors and schedule carry on exactly as they would have) every K steps and re-simulates
/// from the latest one at or before the step wanted. Memory stays bounded: when there are
/// too many snapshots every other one is dropped and K doubles, so a seek re-simulates at
/// most about reached / max_snapshots steps. For an isolated system with the analytic method
/// every state is the analytic solution at its time, so going back is exact in that sense too.
///
/// What the user does to the run (expand the container now, continue a finished run) is
/// recorded with its step and replayed when the timeline re-simulates past it; a new action
/// at an earlier step than the furthest reached discards what was computed after it.

#include <cstddef>
#include <memory>
#include <vector>

#include "swarm/run/side_by_side.h"

namespace swarm {

/// Something done to the runs between steps, replayed at its step.
struct TimelineAction {
  enum class Kind { expand, extend };
  long step = 0;
  Kind kind = Kind::expand;
  double amount = 1;  ///< expand: the factor on R; extend: the steps added
};

struct TimelineLimits {
  std::size_t max_snapshots = 64;
  /// About this much memory for snapshots (bytes), estimated at 256 bytes a particle per run;
  /// fewer snapshots (at least 4) where that would be exceeded.
  double snapshot_bytes = 256e6;
};

class Timeline {
 public:
  Timeline(const System& initial, const RunPlan& plan, const std::vector<Method>& compared,
           const TimelineLimits& limits = {});

  /// The runs at the present step.
  SideBySide& present() { return *present_; }
  const SideBySide& present() const { return *present_; }
  long step() const { return present_->primary().steps_done(); }
  /// The furthest step computed (in the present history).
  long reached() const { return reached_; }
  /// The last step of the run as planned in the present history (with its extensions, also
  /// those recorded ahead of the present step).
  long end_step() const;
  bool finished() const { return present_->finished(); }

  /// Advances the present by up to n steps, fewer at the end of the run; returns the steps
  /// taken. Replays the actions recorded at the steps it passes; beyond reached() it takes
  /// snapshots.
  long advance(long n);
  /// Makes the present the latest snapshot at or before `target` when target is behind the
  /// present or that snapshot is ahead of it (O(N), no stepping): advance(target - step())
  /// then lands on target. For seeks spread over several frames.
  void jump_towards(long target);
  /// Moves the present to step `target`, clamped to [0, end_step()], back or forward, at once;
  /// returns the step it is at.
  long seek(long target);
  /// The step of time t (nearest, clamped to [0, end_step()]).
  long step_of(double t) const;

  /// "Expand now" at the present step (SideBySide::scale_container), recorded.
  void expand_now(double factor);
  /// Lengthens the run by `steps` from the present step on, recorded.
  void extend(long steps);
  const std::vector<TimelineAction>& actions() const { return actions_; }

  /// The steps at which stages begin: the protocol's (k times its steps per stage) and the
  /// expansions by hand, in order.
  std::vector<long> stage_starts() const;
  /// The step at which the stage under way at the present step ends: the protocol stage's
  /// end, else the end of the run.
  long end_of_stage() const;

  std::size_t snapshot_count() const { return snapshots_.size(); }
  /// Steps between snapshots (K), doubled whenever the snapshots are thinned.
  long snapshot_interval() const { return interval_; }

 private:
  struct Snapshot {
    long step;
    std::unique_ptr<SideBySide> runs;
  };
  void apply(const TimelineAction& a);
  /// Drops what was computed after the present step: a new action changes the future.
  void forget_after_present();
  void take_snapshot();

  std::unique_ptr<SideBySide> present_;
  std::vector<Snapshot> snapshots_;  // by step; the first at the start
  std::vector<TimelineAction> actions_;  // by step
  std::size_t max_snapshots_;
  long interval_;
  long reached_ = 0;
  double t0_, dt_;
};

}  // namespace swarm
