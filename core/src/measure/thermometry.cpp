#include "swarm/measure/thermometry.h"

#include <algorithm>
#include <cmath>

namespace swarm {
namespace {

/// The additive tallies behind consecutive readings: sums over intervals can be subtracted,
/// so any window's average follows from two prefix sums.
struct WallSums {
  double impulse_per_area = 0;  ///< sum of P * duration
  double hit_temperature = 0;   ///< sum of T * hits
  std::int64_t hits = 0;
  double elapsed = 0;

  void add(const WallInterval& i) {
    impulse_per_area += i.reading.P * i.duration;
    hit_temperature += i.reading.T * double(i.reading.hits);
    hits += i.reading.hits;
    elapsed += i.duration;
  }
  /// The reading of the intervals counted in *this but not in `before`.
  WallReading since(const WallSums& before) const {
    WallReading w;
    w.hits = hits - before.hits;
    const double time = elapsed - before.elapsed;
    if (time > 0) w.P = (impulse_per_area - before.impulse_per_area) / time;
    if (w.hits > 0) w.T = (hit_temperature - before.hit_temperature) / double(w.hits);
    return w;
  }
};

/// Standard deviation of the values (n - 1) over sqrt(n); none for fewer than two values.
std::optional<double> standard_error(const std::vector<double>& values) {
  const std::size_t n = values.size();
  if (n < 2) return std::nullopt;
  double mean = 0;
  for (double v : values) mean += v;
  mean /= double(n);
  double squares = 0;
  for (double v : values) squares += (v - mean) * (v - mean);
  return std::sqrt(squares / double(n - 1) / double(n));
}

std::vector<WallSums> prefix_sums(const std::vector<WallInterval>& intervals) {
  std::vector<WallSums> prefix(intervals.size() + 1);
  for (std::size_t i = 0; i < intervals.size(); ++i) {
    prefix[i + 1] = prefix[i];
    prefix[i + 1].add(intervals[i]);
  }
  return prefix;
}

}  // namespace

void WallMeter::add(const WallTally& step_tally, double dt, double area) {
  hits_ += step_tally.hits;
  if (step_tally.hits > 0) impulse_per_area_ += step_tally.radial_impulse / area;
  hit_kinetic_energy_ += step_tally.hit_kinetic_energy;
  elapsed_ += dt;
}

WallReading WallMeter::reading() const {
  WallReading w;
  w.hits = hits_;
  if (elapsed_ > 0) w.P = impulse_per_area_ / elapsed_;
  if (hits_ > 0) w.T = 0.5 * hit_kinetic_energy_ / double(hits_);
  return w;
}

void WallMeter::reset() { *this = WallMeter{}; }

WallReading wall_average(const std::vector<WallInterval>& intervals, std::size_t first,
                         std::size_t last) {
  WallSums sums;
  for (std::size_t i = first; i < last && i < intervals.size(); ++i) sums.add(intervals[i]);
  return sums.since(WallSums{});
}

std::vector<WallReading> windowed_wall_averages(const std::vector<WallInterval>& intervals,
                                                double before, double after) {
  const std::vector<WallSums> prefix = prefix_sums(intervals);
  std::vector<WallReading> out;
  out.reserve(intervals.size());
  std::size_t first = 0, last = 0;  // the window is [first, last)
  for (std::size_t i = 0; i < intervals.size(); ++i) {
    const double t = intervals[i].t_end;
    while (last < intervals.size() && intervals[last].t_end <= t + after) ++last;
    // Interval i itself always counts, so a zero window gives its own reading.
    while (first < i && intervals[first].t_end <= t - before) ++first;
    out.push_back(prefix[std::max(last, i + 1)].since(prefix[first]));
  }
  return out;
}

WallEstimate wall_estimate(const std::vector<WallInterval>& intervals, double window,
                           int blocks) {
  WallEstimate e;
  if (intervals.empty()) return e;
  const double end = intervals.back().t_end;
  std::size_t first = intervals.size() - 1;  // the window is [first, size)
  if (window <= 0)
    first = 0;
  else
    while (first > 0 && intervals[first - 1].t_end > end - window) --first;
  const std::size_t count = intervals.size() - first;
  e.mean = wall_average(intervals, first, intervals.size());
  const double start = intervals[first].t_end - intervals[first].duration;
  e.window = end - start;
  e.intervals = int(count);
  e.blocks = int(std::min<std::size_t>(std::size_t(std::max(blocks, 1)), count));
  if (e.blocks < 2 || !(e.window > 0)) return e;

  // Each interval to the sub-window its end falls in; [begin[b], begin[b + 1]) is block b.
  std::vector<std::size_t> begin(std::size_t(e.blocks) + 1, intervals.size());
  std::size_t i = first;
  for (int b = 0; b < e.blocks; ++b) {
    begin[std::size_t(b)] = i;
    const double block_end = start + e.window * double(b + 1) / double(e.blocks);
    while (i < intervals.size() && (intervals[i].t_end <= block_end || b == e.blocks - 1)) ++i;
  }
  std::vector<double> P, T;
  for (int b = 0; b < e.blocks; ++b) {
    const std::size_t from = begin[std::size_t(b)], to = begin[std::size_t(b) + 1];
    if (from == to) continue;
    const WallReading r = wall_average(intervals, from, to);
    P.push_back(r.P);
    if (r.hits > 0) T.push_back(r.T);
  }
  e.blocks = int(P.size());
  e.P_stderr = standard_error(P);
  e.T_stderr = standard_error(T);
  return e;
}

}  // namespace swarm
