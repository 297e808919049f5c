#include "walls_figures.h"

#include <cmath>

#include "swarm/run.h"
#include "swarm/thermometry.h"
#include "swarm/wall.h"

namespace swarmlab::report {

std::optional<NamedFigure> pv_loop_figure(const RunRecord& r) {
  if (r.preset.wall_moves.empty() || r.samples.size() < 3) return std::nullopt;
  // Each sample's P is over a few steps and a few hits: the loop is drawn with the running
  // wall average over 1 % of the run (swarm::windowed_wall_averages), at the sample's volume.
  const std::vector<swarm::WallInterval> intervals = swarm::wall_intervals(r.samples);
  const double half_window = 0.005 * (r.samples.back().t - r.samples.front().t);
  const std::vector<swarm::WallReading> running =
      swarm::windowed_wall_averages(intervals, half_window, half_window);
  Series loop;
  loop.name = "measured at the moving wall (running mean over 1% of the run)";
  loop.colour = 0;
  for (std::size_t i = 0; i < running.size(); ++i) {
    loop.x.push_back(swarm::sphere_volume(r.samples[i + 1].R));
    loop.y.push_back(running[i].P);
  }
  Panel p{{"volume V", "length³"}, {"pressure P", "momentum / (length² time)"}};
  p.y.include_zero = true;
  p.series.push_back(loop);
  // A free gas (J = 0) moved slowly follows the adiabat P V^(5/3) = P0 V0^(5/3), with P0 the
  // ideal-gas pressure 2 KE0 / (3 V0) of its start.
  if (r.preset.J == 0) {
    const double V0 = swarm::sphere_volume(r.samples.front().R);
    const double P0 = 2 * r.samples.front().KE / (3 * V0);
    Series adiabat;
    adiabat.name = "adiabat P V^(5/3) = const (a slow, reversible move)";
    adiabat.colour = 7;
    adiabat.dashed = true;
    for (double V : loop.x) {
      adiabat.x.push_back(V);
      adiabat.y.push_back(P0 * std::pow(V0 / V, 5.0 / 3.0));
    }
    p.series.push_back(adiabat);
    p.note = "the loop encloses the net work done on the gas; the gas ends warmer";
  }
  return NamedFigure{"pv-loop", Figure{"P-V loop of a moving wall", r.preset.name, {p}}};
}

}  // namespace swarmlab::report
