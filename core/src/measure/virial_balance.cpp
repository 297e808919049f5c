#include "swarm/measure/virial_balance.h"

#include <algorithm>
#include <cmath>

#include "swarm/measure/blocking.h"

namespace swarm {

std::optional<VirialBalance> virial_balance(const std::vector<VirialInterval>& intervals,
                                            double from) {
  std::size_t first = 0;
  // An interval starts at or after `from` up to rounding of its own length (a start put at
  // an interval's start by wall_time_averages, read back from t_end - duration).
  while (first < intervals.size() &&
         intervals[first].t_end - intervals[first].duration < from - 1e-9 * intervals[first].duration)
    ++first;
  if (intervals.size() - first < 8) return std::nullopt;
  std::vector<double> difference_dt, duration;  // (3PV - (2KE - 2U)) dt, dt
  double wall = 0, kinetic = 0, G_squared = 0, time = 0;  // each integrated over time
  for (std::size_t i = first; i < intervals.size(); ++i) {
    const VirialInterval& v = intervals[i];
    wall += v.wall * v.duration;
    kinetic += v.kinetic * v.duration;
    G_squared += 0.5 * (v.G_start * v.G_start + v.G_end * v.G_end) * v.duration;
    time += v.duration;
    difference_dt.push_back((v.wall - v.kinetic) * v.duration);
    duration.push_back(v.duration);
  }
  const std::optional<BlockingError> blocked = blocking_error_of_ratio(difference_dt, duration);
  if (!blocked || !(time > 0)) return std::nullopt;
  VirialBalance out;
  out.start = intervals[first].t_end - intervals[first].duration;
  out.end = intervals.back().t_end;
  out.intervals = long(intervals.size() - first);
  out.wall = wall / time;
  out.kinetic = kinetic / time;
  out.G_start = intervals[first].G_start;
  out.G_end = intervals.back().G_end;
  out.imbalance = -(out.G_end - out.G_start) / (out.end - out.start);
  out.residual = out.wall - out.kinetic - out.imbalance;
  out.error = std::min(std::sqrt(2 * G_squared / time) / (out.end - out.start), blocked->se);
  out.holds = std::abs(out.imbalance) <= kVirialBalanceErrors * out.error;
  return out;
}

}  // namespace swarm
