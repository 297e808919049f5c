#include "report/pv_loop.h"

#include "swarm/measure/thermometry.h"
#include "swarm/physics/wall.h"

namespace swarmlab::report {

PvLoop pv_loop(const std::vector<swarm::Sample>& samples, double half_window,
               double sphere_radius) {
  PvLoop loop;
  if (samples.size() < 2) return loop;
  // Interval i ends at sample i + 1 (the first sample covers no step).
  const std::vector<swarm::WallInterval> intervals = swarm::wall_intervals(samples);
  const std::vector<swarm::WallReading> running =
      swarm::windowed_wall_averages(intervals, half_window, half_window);
  std::size_t innermost = 0;
  for (std::size_t i = 0; i < running.size(); ++i)
    if (samples[i + 1].R < samples[innermost + 1].R) innermost = i;
  for (std::size_t i = 0; i < running.size(); ++i) {
    const double V = swarm::sphere_volume(samples[i + 1].R - sphere_radius);
    if (i <= innermost) {
      loop.V_in.push_back(V);
      loop.P_in.push_back(running[i].P);
    } else {
      if (loop.V_out.empty()) {
        loop.V_out.push_back(loop.V_in.back());
        loop.P_out.push_back(loop.P_in.back());
      }
      loop.V_out.push_back(V);
      loop.P_out.push_back(running[i].P);
    }
  }
  return loop;
}

}  // namespace swarmlab::report
