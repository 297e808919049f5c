#include "ui/state/plot_series.h"

#include <algorithm>
#include <cmath>

#include "swarm/measure/thermometry.h"
#include "swarm/run/run.h"

namespace swarmlab {

void SampleSeries::update(LiveRun& live, double average_window) {
  const auto& samples = live.primary().samples();
  if (run == live.id() && count == samples.size() && window == average_window) return;
  run = live.id();
  count = samples.size();
  window = average_window;
  for (auto* v : {&t, &P, &T, &P_mean, &T_mean, &t_all, &KE, &PE, &E, &drift}) v->clear();
  // P and T over a trailing window, by the core's one definition of a wall average.
  const std::vector<swarm::WallInterval> intervals = swarm::wall_intervals(samples);
  const std::vector<swarm::WallReading> means =
      swarm::windowed_wall_averages(intervals, average_window, 0);
  for (std::size_t i = 0; i < intervals.size(); ++i) {
    const swarm::WallReading& w = intervals[i].reading;
    t.push_back(intervals[i].t_end);
    P.push_back(w.P);
    // Without a hit there is no temperature: a gap in the curve, not T = 0.
    T.push_back(w.hits > 0 ? w.T : std::nan(""));
    P_mean.push_back(means[i].P);
    T_mean.push_back(means[i].hits > 0 ? means[i].T : std::nan(""));
  }
  for (const swarm::Sample& s : samples) {
    t_all.push_back(s.t);
    KE.push_back(s.KE);
    PE.push_back(s.PE);
    E.push_back(s.E);
    drift.push_back(swarm::relative_energy_change(samples.front(), s.E));
  }
}

void ProjectCache::update(LiveRun& live, const swarm::Preset& preset, const ProjectPlots& plots) {
  const auto& samples = live.primary().samples();
  if (run == live.id() && count == samples.size()) return;
  run = live.id();
  count = samples.size();
  series = project_series(samples);
  // Each sample's P is over a few hits: the loop is drawn with the running wall average
  // over 3 % of the run, as in the CLI's pv-loop figure.
  if (plots.pv_loop)
    loop = report::pv_loop(samples, 0.015 * preset.duration, preset.sphere_radius.value_or(0.0));
  if (plots.speeds) {
    // About sqrt(n) bins: enough particles in each to see the shape.
    const std::size_t n = live.system().particles.size();
    const int bins = std::clamp(int(std::lround(std::sqrt(double(n)))), 5, 40);
    speeds = swarm::check_speeds(live.system(), bins);
    histogram = histogram_series(speeds.histogram);
  }
}

}  // namespace swarmlab
