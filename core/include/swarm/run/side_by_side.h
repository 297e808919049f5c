#pragma once
/// Several methods run in lockstep from one initial state, so that their orbits and energies
/// can be compared at the same instants (e.g. Euler against Euler-Cromer against analytic).

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "swarm/run/run.h"

namespace swarm {

/// How far a compared method has strayed from the primary one.
struct ComparisonSample {
  double t = 0;
  double E = 0;               ///< the compared run's total energy
  double position_error = 0;  ///< max over particles of |r_compared - r_primary|
};

/// How far one numerical method has strayed from the exact solution, at the primary's samples.
struct ErrorFromExact {
  Method method;
  std::vector<double> t;
  std::vector<double> position_error;  ///< max_i |r_i - r_i(analytic)| (length)
};

class SideBySide {
 public:
  struct Track {
    Method method;
    std::unique_ptr<Run> run;
    std::vector<ComparisonSample> samples;
  };

  SideBySide(const System& initial, const RunPlan& plan, const std::vector<Method>& compared);
  /// An independent copy (every run cloned) that carries on exactly as this one would.
  SideBySide(const SideBySide& other);
  SideBySide& operator=(const SideBySide&) = delete;

  /// Advances every run by up to n steps; returns the steps taken.
  long advance(long n);
  /// Runs to the end, calling progress(fraction done) at least about once a second.
  void finish(const std::function<void(double)>& progress = {});
  /// At the end, or stopped because one of the runs failed.
  bool finished() const;
  /// "" while every run's numbers are finite, else the first failure, prefixed with the
  /// method's name when it is a compared run's.
  std::string failure() const;

  Run& primary() { return *primary_; }
  const Run& primary() const { return *primary_; }
  /// The compared runs, in the order asked for.
  const std::vector<Track>& tracks() const { return tracks_; }

  /// The run of the exact solution: the primary when it is analytic, else the first compared
  /// analytic run; null when no analytic method runs.
  Run* exact() { return exact_; }
  /// The distance of every numerical run (the primary first) from exact(), recorded at the
  /// primary's samples; empty when no analytic method runs.
  const std::vector<ErrorFromExact>& errors_from_exact() const { return errors_; }

  /// Grows every run's container by `factor` at once (Run::expand_now, which may also end a
  /// stage by hand). No particle is touched, so no work is done.
  void scale_container(double factor);
  /// Lengthens every run by `steps` (Run::extend).
  void extend(long steps);

 private:
  void record();

  std::unique_ptr<Run> primary_;
  std::vector<Track> tracks_;
  Run* exact_ = nullptr;
  std::vector<ErrorFromExact> errors_;
};

/// max_i |a_i.r - b_i.r| over two systems of the same particles.
double max_position_difference(const System& a, const System& b);

}  // namespace swarm
