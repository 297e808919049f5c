#pragma once
// The simulation behind the window: the preset's run, the methods run beside it from the same
// start, the errors between them, and the trails of the particles being followed.

#include <deque>
#include <memory>
#include <vector>

#include "swarm/preset.h"
#include "swarm/run.h"

namespace swarmlab {

/// How far one method has strayed from the exact solution, at the primary run's samples.
struct ErrorTrack {
  swarm::Method method;
  std::vector<double> t;
  std::vector<double> position_error;  ///< max_i |r_i - r_i(analytic)|, length
};

/// The recent path of one particle, in the lab frame.
struct Trail {
  std::size_t particle = 0;
  std::deque<Eigen::Vector3f> points;
};

class LiveRun {
 public:
  /// The preset must be valid (swarm::preset_error(preset) empty).
  explicit LiveRun(const swarm::Preset& preset);

  /// Advances every method by up to `steps` steps in lockstep; returns the steps taken
  /// (fewer at the end of the run).
  long advance(long steps);
  bool finished() const { return primary_->finished(); }

  const swarm::Preset& preset() const { return preset_; }
  /// Different for every LiveRun ever made: caches of derived data key on it.
  long id() const { return id_; }
  swarm::Run& primary() { return *primary_; }
  const swarm::System& system() { return primary_->engine().system(); }
  double time() { return primary_->engine().time(); }

  /// The runs of the preset's `compare` list, in its order.
  std::size_t compared_count() const { return compared_.size(); }
  swarm::Run& compared(std::size_t i) { return *compared_[i]; }
  swarm::Method compared_method(std::size_t i) const { return preset_.compare[i]; }
  /// The run of the exact solution when the primary is numerical and "analytic" is compared:
  /// its positions are drawn as ghosts. Null otherwise.
  swarm::Run* analytic_reference() { return analytic_reference_; }
  /// Errors of every numerical method against the analytic run (empty without one).
  const std::vector<ErrorTrack>& errors() const { return errors_; }

  /// Grows the container of every run by `factor` at once (the "expand now" button). No
  /// particle is touched, so no work is done.
  void expand_container(double factor);

  /// Follows these particles with trails (indices beyond N are ignored).
  void follow(const std::vector<std::size_t>& particles);
  const std::vector<Trail>& trails() const { return trails_; }

 private:
  void record_errors();
  void record_trails();

  long id_;
  swarm::Preset preset_;
  std::unique_ptr<swarm::Run> primary_;
  std::vector<std::unique_ptr<swarm::Run>> compared_;
  swarm::Run* analytic_reference_ = nullptr;
  std::vector<ErrorTrack> errors_;
  std::vector<Trail> trails_;
  long trail_stride_ = 1;  // steps between trail points: about 150 points per period
  long steps_since_trail_point_ = 0;
};

}  // namespace swarmlab
