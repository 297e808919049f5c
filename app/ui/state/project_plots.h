#pragma once
// Which plots of the Appendix B projects fit a preset, and their series, built from the run's
// samples and the core's speed histogram (no ImGui: tested natively). The Plots panel's
// "Projects" tab draws them.

#include <vector>

#include "swarm/preset/preset.h"
#include "swarm/run/run.h"
#include "swarm/measure/speed_distribution.h"

namespace swarmlab {

/// The project plots a preset's features call for.
struct ProjectPlots {
  bool motion = false;   ///< gravity or a floor: CM height and swarm size over time
  bool books = false;    ///< a floor, drag, a moving or hot wall: the energy books over time
  bool pv_loop = false;  ///< a moving wall: P against V, the way in and the way out
  bool speeds = false;   ///< a container, hot wall or hard spheres: speeds against the Maxwellian
  bool any() const { return motion || books || pv_loop || speeds; }
};
ProjectPlots project_plots_for(const swarm::Preset& p);

/// The samples as time series: CM height and size, and the energy books beside E - E0.
struct ProjectSeries {
  std::vector<double> t, cm_height, size;
  std::vector<double> wall_work, wall_heat, drag_loss, net, energy_change;  // energy
};
ProjectSeries project_series(const std::vector<swarm::Sample>& samples);

/// A speed histogram as plot series: bin centres with the measured density and the Maxwell
/// density at each.
struct HistogramSeries {
  std::vector<double> x, measured, maxwell;
};
HistogramSeries histogram_series(const swarm::SpeedHistogram& h);

}  // namespace swarmlab
