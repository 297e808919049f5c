#pragma once
// The simulation behind the window: the preset's run and the methods run beside it from the
// same start (swarm::SideBySide, as in the CLI), and the trails of the particles being followed.

#include <deque>
#include <memory>
#include <vector>

#include "swarm/preset/preset.h"
#include "swarm/run/run.h"
#include "swarm/run/side_by_side.h"
#include "swarm/run/timeline.h"

namespace swarmlab {

/// The recent path of one particle, in the lab frame.
struct Trail {
  std::size_t particle = 0;
  std::deque<Eigen::Vector3f> points;
};

class LiveRun {
 public:
  /// The preset must be valid (swarm::preset_error(preset) empty).
  /// threads: the engine's (EngineConfig::threads); 0: the default.
  explicit LiveRun(const swarm::Preset& preset, int threads = 0);

  /// Advances every method by up to `steps` steps in lockstep; returns the steps taken
  /// (fewer at the end of the run).
  long advance(long steps);
  bool finished() const { return timeline_.finished(); }

  const swarm::Preset& preset() const { return preset_; }
  /// Different for every LiveRun ever made: caches of derived data key on it.
  long id() const { return id_; }
  swarm::Run& primary() { return runs().primary(); }
  const swarm::System& system() { return primary().engine().system(); }
  double time() { return primary().engine().time(); }

  /// The runs of the preset's `compare` list, in its order.
  std::size_t compared_count() const { return runs().tracks().size(); }
  swarm::Run& compared(std::size_t i) { return *runs().tracks()[i].run; }
  swarm::Method compared_method(std::size_t i) const { return runs().tracks()[i].method; }
  /// The run of the exact solution when the primary is numerical and "analytic" is compared:
  /// its positions are drawn as ghosts. Null otherwise.
  swarm::Run* analytic_reference() { return runs().exact() != &primary() ? runs().exact() : nullptr; }
  /// Errors of every numerical method against the analytic run (empty without one).
  const std::vector<swarm::ErrorFromExact>& errors() const { return runs().errors_from_exact(); }

  /// Grows the container of every run by `factor` at once (the "expand now" button), which
  /// ends a stage by hand (swarm::Run::expand_now), recorded in the timeline. No particle is
  /// touched, so no work is done.
  void expand_container(double factor) { timeline_.expand_now(factor); }

  // Time: the runs move back and forth over the steps reached (swarm::Timeline).
  const swarm::Timeline& timeline() const { return timeline_; }
  long step() const { return timeline_.step(); }
  /// Jumps to the timeline's latest snapshot at or before `target` when that moves the run
  /// (then advance() lands on target); the trails start again where it lands.
  void jump_towards(long target);
  /// Continues the run by `steps` more steps (a finished run that plays on).
  void extend(long steps) { timeline_.extend(steps); }

  /// Follows these particles with trails (indices beyond N are ignored).
  void follow(const std::vector<std::size_t>& particles);
  const std::vector<Trail>& trails() const { return trails_; }

 private:
  void record_trails();

  long id_;
  swarm::Preset preset_;
  swarm::SideBySide& runs() { return timeline_.present(); }
  const swarm::SideBySide& runs() const { return timeline_.present(); }

  swarm::Timeline timeline_;
  std::vector<Trail> trails_;
  long trail_stride_ = 1;  // steps between trail points: about 150 points per period
  long steps_since_trail_point_ = 0;
};

}  // namespace swarmlab
