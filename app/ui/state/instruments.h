#pragma once
// The measuring instruments' state: the stopwatch, the period meter and the x(t) record of the
// selected particle, and P and T with their uncertainty. The core measures (swarm::Stopwatch,
// swarm::PeriodMeter, swarm::wall_estimate); this only feeds them once per frame and keeps
// what the panels show.

#include <cstddef>
#include <optional>
#include <vector>

#include "swarm/measure/period_meter.h"
#include "swarm/measure/stopwatch.h"
#include "swarm/measure/thermometry.h"
#include "swarm/measure/virial_balance.h"
#include "ui/state/live_run.h"

namespace swarmlab {

/// The selected particle, timed since it was selected (or since the run started).
struct ParticleTrack {
  std::size_t particle = 0;
  long run = 0;  ///< LiveRun::id() it belongs to
  swarm::PeriodMeter meter{0.0};
  /// Its x coordinate about the centre of mass, once per frame (length), and the time.
  std::vector<double> t, x;
  double x_start = 0;  ///< x when timing started: the plot's marker
  double last_t = 0;
};

/// The ± to show beside a wall reading (P or T). The error from history always; the error from
/// the window's own parts (the short-history fallback, 0.9x to 1.8x the true error at best and
/// more at short windows, thermometry.h) only while it is smaller than the value: a ± as large
/// as the mean says nothing yet ("84 ± 1.7e+02"), so it is withheld until it means something.
std::optional<double> shown_wall_error(double value, const std::optional<double>& error,
                                       swarm::WallErrorSource source);

struct Instruments {
  swarm::Stopwatch stopwatch;
  std::optional<ParticleTrack> track;  ///< while a particle is selected
  /// P and T over the plots' averaging window, recomputed when a sample arrives.
  swarm::WallEstimate wall;
  /// The virial balance over the same window, where it applies (swarm/measure/virial_balance.h);
  /// recomputed with `wall`, not per frame: its cost grows with the window.
  std::optional<swarm::VirialBalance> virial;
  long wall_run = 0;
  std::size_t wall_samples = 0;
  double wall_window = -1;

  /// Once per frame, after the simulation advanced: the stopwatch reads the simulated clock,
  /// the selected particle's meter gets its position and velocity about the CM, P and T (in a
  /// container) follow the new samples over average_window. A new run, a new selection or a
  /// clock that went back starts the timing afresh.
  void update(LiveRun& run, std::optional<std::size_t> selected, double average_window,
              bool container);
};

}  // namespace swarmlab
