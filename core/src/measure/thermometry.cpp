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

/// The errors from the window's own parts, [first, end) (see wall_estimate): the history
/// errors of its sub-windows a quarter and a sixteenth as long, each with four quarters'
/// worth of history inside the window. The variance of a sub-window's sum, S(w) = w^2 se(w)^2,
/// grows like w^alpha: alpha is measured between the two, held to [0, 1] (0: regular motion,
/// whose sums stay bounded; 1: independent parts) and carried on from a quarter to the whole.
/// False with fewer than kWallPartsIntervals intervals or a wall that moved in the window.
bool errors_from_parts(const std::vector<WallInterval>& intervals, std::size_t first,
                       WallEstimate& e) {
  if (intervals.size() - first < kWallPartsIntervals) return false;
  const std::vector<WallInterval> window(intervals.begin() + long(first), intervals.end());
  for (const WallInterval& i : window)
    if (i.R != window.back().R) return false;
  // A hair under a quarter, so that four of them fit in the window whatever the rounding.
  const double quarter = e.window / kWallHistoryWindows * (1 - 1e-9);
  WallEstimate q, s;
  if (!errors_from_history(window, window.size() - 1, quarter, q) ||
      !errors_from_history(window, window.size() - 1, quarter / 4, s))
    return false;
  // se(whole) = se(quarter) / 4 * sqrt(S(quarter) * 4^alpha / S(quarter))
  //           = se(quarter) / 4 * g, g = sqrt(S(quarter) / S(sixteenth)) held to [1, 2].
  auto carried = [](const std::optional<double>& quarter_se,
                    const std::optional<double>& sixteenth_se) -> std::optional<double> {
    if (!quarter_se || !sixteenth_se) return std::nullopt;
    const double g = *sixteenth_se > 0 ? 4 * *quarter_se / *sixteenth_se : 2.0;
    return *quarter_se / 4 * std::clamp(g, 1.0, 2.0);
  };
  e.P_stderr = carried(q.P_stderr, s.P_stderr);
  e.T_stderr = carried(q.T_stderr, s.T_stderr);
  if (!e.P_stderr) return false;
  e.source = WallErrorSource::parts;
  return true;
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
  errors_from_parts(intervals, first, e);
  return e;
}

}  // namespace swarm
