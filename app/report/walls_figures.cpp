#include "report/walls_figures.h"

#include <cmath>
#include <cstdio>

#include "report/pv_loop.h"
#include "swarm/measure/thermometry.h"
#include "swarm/physics/wall.h"
#include "swarm/run/run.h"

namespace swarmlab::report {

std::optional<NamedFigure> pv_loop_figure(const RunRecord& r) {
  if (r.preset.wall_moves.empty() || r.samples.size() < 3) return std::nullopt;
  // The running wall average over 3 % of the run; the way in and the way out in their own
  // colours.
  const double half_window = 0.015 * (r.samples.back().t - r.samples.front().t);
  const PvLoop loop = pv_loop(r.samples, half_window, r.preset.sphere_radius.value_or(0.0));
  Series in, out;
  in.name = "squeezing: the wall moving in";
  in.colour = 0;
  in.x = loop.V_in, in.y = loop.P_in;
  out.name = "letting out: the wall moving out";
  out.colour = 1;
  out.x = loop.V_out, out.y = loop.P_out;
  Panel p{{"volume V", "length³"}, {"pressure P", "momentum / (length² time)"}};
  p.y.include_zero = true;
  p.series.push_back(in);
  if (!out.x.empty()) p.series.push_back(out);
  // A free gas (J = 0) moved slowly follows the adiabat P V^(5/3) = P0 V0^(5/3), with P0 the
  // ideal-gas pressure 2 KE0 / (3 V0) of its start.
  if (r.preset.J == 0) {
    const double V0 = swarm::sphere_volume(r.samples.front().R - r.preset.sphere_radius.value_or(0.0));
    const double P0 = 2 * r.samples.front().KE / (3 * V0);
    Series adiabat;
    adiabat.name = "adiabat P V^(5/3) = const (a slow, reversible move)";
    adiabat.colour = 7;
    adiabat.dashed = true;
    std::vector<double> volumes = in.x;
    volumes.insert(volumes.end(), out.x.begin(), out.x.end());
    for (double V : volumes) {
      adiabat.x.push_back(V);
      adiabat.y.push_back(P0 * std::pow(V0 / V, 5.0 / 3.0));
    }
    p.series.push_back(adiabat);
    p.note = "running means over 3% of the run; the gas ends warmer than it began";
  }
  return NamedFigure{"pv-loop", Figure{"P-V loop of a moving wall", r.preset.name, {p}}};
}

std::optional<NamedFigure> speed_histogram_figure(const RunRecord& r) {
  if (!r.final_speeds || r.final_speeds->n == 0 || r.final_speeds->T <= 0) return std::nullopt;
  const swarm::SpeedCheck& c = *r.final_speeds;
  const swarm::SpeedHistogram& h = c.histogram;
  const double width = h.x_max / double(h.density.size());
  Series measured, maxwell;
  measured.name = "the particles at the end";
  measured.mark = Mark::line_and_points;
  measured.colour = 0;
  maxwell.name = "Maxwell distribution at their T";
  maxwell.colour = 3;
  maxwell.dashed = true;
  for (std::size_t b = 0; b < h.density.size(); ++b) {
    const double x = (double(b) + 0.5) * width;
    measured.x.push_back(x), measured.y.push_back(h.density[b]);
    maxwell.x.push_back(x), maxwell.y.push_back(h.maxwell[b]);
  }
  Panel p{{"speed v √(m/T)", ""}, {"probability density", ""}};
  p.y.include_zero = true;
  p.series = {measured, maxwell};
  char note[200];
  std::snprintf(note, sizeof note,
                "T = %.4g, N = %zu; Kolmogorov-Smirnov √N D = %.3g (< 1.63: Maxwellian at 1 %%)",
                c.T, c.n, std::sqrt(double(c.n)) * c.ks_distance);
  p.note = note;
  return NamedFigure{"speeds", Figure{"Speeds at the end against the Maxwellian", r.preset.name, {p}}};
}

}  // namespace swarmlab::report
