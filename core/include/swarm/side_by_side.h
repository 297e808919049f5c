#pragma once
/// Several methods run in lockstep from one initial state, so that their orbits and energies
/// can be compared at the same instants (e.g. Euler against Euler-Cromer against analytic).

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "swarm/run.h"

namespace swarm {

/// How far a compared method has strayed from the primary one.
struct ComparisonSample {
  double t = 0;
  double E = 0;               ///< the compared run's total energy
  double position_error = 0;  ///< max over particles of |r_compared - r_primary|
};

class SideBySide {
 public:
  struct Track {
    Method method;
    std::unique_ptr<Run> run;
    std::vector<ComparisonSample> samples;
  };

  SideBySide(const System& initial, const RunPlan& plan, const std::vector<Method>& compared);

  /// Advances every run by up to n steps; returns the steps taken.
  long advance(long n);
  void finish(const std::function<void(double)>& progress = {});
  /// At the end, or stopped because one of the runs failed.
  bool finished() const;
  /// "" while every run's numbers are finite, else the first failure, prefixed with the
  /// method's name when it is a compared run's.
  std::string failure() const;

  Run& primary() { return *primary_; }
  const std::vector<Track>& tracks() const { return tracks_; }

 private:
  void record();

  std::unique_ptr<Run> primary_;
  std::vector<Track> tracks_;
};

/// max_i |a_i.r - b_i.r| over two systems of the same particles.
double max_position_difference(const System& a, const System& b);

}  // namespace swarm
