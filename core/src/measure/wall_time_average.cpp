#include "swarm/measure/wall_time_average.h"

#include <cmath>

namespace swarm {
namespace {

struct Series {
  std::vector<double> impulse_per_area, duration, hit_energy, hits;  // P dt, dt, T hits, hits
};

Series series_from(const std::vector<WallInterval>& intervals, std::size_t first) {
  Series s;
  for (std::size_t i = first; i < intervals.size(); ++i) {
    const WallInterval& w = intervals[i];
    s.impulse_per_area.push_back(w.reading.P * w.duration);
    s.duration.push_back(w.duration);
    s.hit_energy.push_back(w.reading.T * double(w.reading.hits));
    s.hits.push_back(double(w.reading.hits));
  }
  return s;
}

}  // namespace

WallTimeAverages wall_time_averages(const std::vector<WallInterval>& intervals,
                                    const std::vector<VirialInterval>& virial) {
  WallTimeAverages out;
  const std::size_t n = intervals.size();
  if (n < 8) return out;
  const bool judged = virial.size() == n;
  std::size_t best = 0, closest = 0;
  double most = -1, fewest_errors = INFINITY;
  for (int k = 0; k <= 10; ++k) {
    const std::size_t first = n * std::size_t(k) / 20;
    if (judged) {
      const double from = intervals[first].t_end - intervals[first].duration;
      const std::optional<VirialBalance> b = virial_balance(virial, from);
      if (!b) continue;
      const double errors = b->error > 0 ? std::abs(b->imbalance) / b->error
                                         : (b->imbalance == 0 ? 0.0 : INFINITY);
      if (errors < fewest_errors) fewest_errors = errors, closest = first;
      if (!b->holds) continue;
    }
    const Series s = series_from(intervals, first);
    const auto P = blocking_error_of_ratio(s.impulse_per_area, s.duration);
    if (P && P->effective_count > most) most = P->effective_count, best = first;
  }
  if (judged && most < 0) best = closest;  // no start balances: the one closest to it
  if (judged)
    out.virial = virial_balance(virial, intervals[best].t_end - intervals[best].duration);
  const Series s = series_from(intervals, best);
  out.start = intervals[best].t_end - intervals[best].duration;
  out.intervals = long(n - best);
  out.P = blocking_error_of_ratio(s.impulse_per_area, s.duration);
  out.T = blocking_error_of_ratio(s.hit_energy, s.hits);
  return out;
}

}  // namespace swarm
