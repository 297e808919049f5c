#pragma once
// The plots' series computed from the live run and kept between frames, so that a plot tab
// drawn every frame does not compute them again: rebuilt whenever the run (its id) or its
// sample count changes, so they only ever hold what the state itself determines.

#include <cstddef>
#include <vector>

#include "report/pv_loop.h"
#include "swarm/measure/speed_distribution.h"
#include "ui/state/live_run.h"
#include "ui/state/project_plots.h"

namespace swarmlab {

/// The sample series of the primary run, with P and T averaged over a trailing time window.
/// Rebuilt only when a sample arrives, the run restarts or the window changes.
struct SampleSeries {
  long run = 0;  ///< LiveRun::id()
  std::size_t count = 0;
  double window = -1;
  std::vector<double> t, P, T, P_mean, T_mean;  ///< from the second sample on
  std::vector<double> t_all, KE, PE, E, drift;  ///< every sample

  void update(LiveRun& live, double average_window);
};

/// The Projects tab's series (project_plots.h), rebuilt only when a sample arrives or the run
/// restarts.
struct ProjectCache {
  long run = 0;  ///< LiveRun::id()
  std::size_t count = 0;
  ProjectSeries series;
  report::PvLoop loop;
  swarm::SpeedCheck speeds;
  HistogramSeries histogram;

  void update(LiveRun& live, const swarm::Preset& preset, const ProjectPlots& plots);
};

}  // namespace swarmlab
