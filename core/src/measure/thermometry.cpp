#include "swarm/measure/thermometry.h"

#include <algorithm>
#include <cmath>

#include "swarm/measure/blocking.h"

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

namespace {

/// The standard deviation of overlapping windows' means, as the error of one window's mean:
/// the variance is corrected by history / (history - window) for the mean they share. None
/// for fewer than two values.
std::optional<double> overlapping_windows_error(const std::vector<double>& means,
                                                double history, double window) {
  const std::size_t n = means.size();
  if (n < 2) return std::nullopt;
  double mean = 0;
  for (double m : means) mean += m;
  mean /= double(n);
  double squares = 0;
  for (double m : means) squares += (m - mean) * (m - mean);
  return std::sqrt(squares / double(n) * history / (history - window));
}

/// The errors from the history before the window [first, end) (see wall_estimate); false when
/// there is too little of it at the wall's present radius.
bool errors_from_history(const std::vector<WallInterval>& intervals, std::size_t first,
                         double window, WallEstimate& e) {
  const std::size_t n = intervals.size();
  const double R = intervals.back().R, end = intervals.back().t_end;
  for (std::size_t i = first; i < n; ++i)
    if (intervals[i].R != R) return false;
  auto start_of = [&](std::size_t i) { return intervals[i].t_end - intervals[i].duration; };
  std::size_t h = first;  // the history is [h, n)
  while (h > 0 && intervals[h - 1].R == R && start_of(h - 1) >= end - kWallHistoryLimit * window)
    --h;
  const double history = end - start_of(h);
  if (history < kWallHistoryWindows * window) return false;

  std::vector<WallSums> prefix(n - h + 1);  // prefix[k]: the sums over [h, h + k)
  for (std::size_t i = h; i < n; ++i) {
    prefix[i - h + 1] = prefix[i - h];
    prefix[i - h + 1].add(intervals[i]);
  }
  std::vector<double> P, T;
  std::size_t from = h;  // the window ending at interval j is [from, j]
  for (std::size_t j = h; j < n; ++j) {
    const double t = intervals[j].t_end;
    if (t - window < start_of(h) - 1e-9 * window) continue;  // no whole window ends here yet
    while (intervals[from].t_end <= t - window) ++from;
    const WallReading r = prefix[j - h + 1].since(prefix[from - h]);
    P.push_back(r.P);
    if (r.hits > 0) T.push_back(r.T);
  }
  e.P_stderr = overlapping_windows_error(P, history, window);
  e.T_stderr = overlapping_windows_error(T, history, window);
  if (!e.P_stderr) return false;
  e.source = WallErrorSource::history;
  e.history = history;
  return true;
}

/// The errors by blocking over the window's intervals [first, end): P as impulse over time,
/// T as hit energy over hits, each interval weighted as wall_average weighs it.
void errors_by_blocking(const std::vector<WallInterval>& intervals, std::size_t first,
                        WallEstimate& e) {
  std::vector<double> impulse, duration, hit_energy, hits;
  for (std::size_t i = first; i < intervals.size(); ++i) {
    const WallInterval& w = intervals[i];
    impulse.push_back(w.reading.P * w.duration);
    duration.push_back(w.duration);
    hit_energy.push_back(w.reading.T * double(w.reading.hits));
    hits.push_back(double(w.reading.hits));
  }
  const auto P = blocking_error_of_ratio(impulse, duration);
  if (!P) return;
  e.source = WallErrorSource::blocking;
  e.P_stderr = P->se;
  if (const auto T = blocking_error_of_ratio(hit_energy, hits)) e.T_stderr = T->se;
}

}  // namespace

WallEstimate wall_estimate(const std::vector<WallInterval>& intervals, double window) {
  WallEstimate e;
  if (intervals.empty()) return e;
  const double end = intervals.back().t_end;
  std::size_t first = intervals.size() - 1;  // the window is [first, size)
  if (window <= 0)
    first = 0;
  else
    while (first > 0 && intervals[first - 1].t_end > end - window) --first;
  e.mean = wall_average(intervals, first, intervals.size());
  e.window = end - (intervals[first].t_end - intervals[first].duration);
  e.intervals = int(intervals.size() - first);
  if (window > 0 && errors_from_history(intervals, first, window, e)) return e;
  errors_by_blocking(intervals, first, e);
  return e;
}

}  // namespace swarm
