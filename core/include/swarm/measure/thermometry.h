#pragma once
/// Pressure and temperature measured at the container wall (paper section III.A).
/// Convention (k_B = 1): P = sum |dp_r| / (4 pi R^2 t_interval), and T is half the mean
/// kinetic energy of the particles that hit the wall in the interval. Particles reach the
/// wall at a rate proportional to their speed, so for an ideal gas the hitters' mean kinetic
/// energy is 2T: with this convention T equals the ideal-gas temperature and P V = N T holds
/// when J = 0.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "swarm/physics/wall.h"

namespace swarm {

struct WallReading {
  double P = 0;  ///< pressure, force per area
  double T = 0;  ///< temperature, energy units; 0 when nothing hit the wall
  std::int64_t hits = 0;
};

/// Accumulates the wall tallies of consecutive steps.
class WallMeter {
 public:
  /// `area` is the wall's during the step (sphere_area, or swept_area for a wall that moved):
  /// the pressure divides by it.
  void add(const WallTally& step_tally, double dt, double area);
  WallReading reading() const;
  void reset();

 private:
  std::int64_t hits_ = 0;
  double impulse_per_area_ = 0;
  double hit_kinetic_energy_ = 0;
  double elapsed_ = 0;  // time covered by the tallies added: P divides by it
};

/// One interval's wall reading and the time it covers.
struct WallInterval {
  double t_end = 0;     ///< when the interval ended (time)
  double duration = 0;  ///< its length (time)
  WallReading reading;
  double R = 0;  ///< the wall's radius at its end (length): a wall that moved starts a new state
};

/// P and T over the consecutive intervals [first, last), as one WallMeter over all of them would
/// read: P is the total impulse per area over the total time (each interval weighted by its
/// duration), T the mean over every hit (each interval weighted by its hits), so an interval
/// without hits adds nothing to T instead of counting as T = 0. T = 0 when nothing hit.
WallReading wall_average(const std::vector<WallInterval>& intervals, std::size_t first,
                         std::size_t last);

/// For every interval i, the wall_average over the intervals that end in
/// (t_end_i - before, t_end_i + after], and interval i itself: a trailing window when
/// after = 0 (the live plots), a centred one when before = after (the report's figures).
/// O(number of intervals) in all.
std::vector<WallReading> windowed_wall_averages(const std::vector<WallInterval>& intervals,
                                                double before, double after);

/// Where a WallEstimate's standard errors come from.
enum class WallErrorSource {
  none,     ///< too little history and too few intervals for any: no ± rather than a wrong one
  history,  ///< the spread of the means of earlier windows of the same length
  parts,    ///< the window's own sub-windows, carried on to its length (too little history)
};

/// P and T over a trailing window, as numbers to read off with their uncertainty.
struct WallEstimate {
  WallReading mean;   ///< the wall_average over the window's intervals
  double window = 0;  ///< the time those intervals cover
  int intervals = 0;  ///< how many intervals the window holds
  WallErrorSource source = WallErrorSource::none;
  /// With source history: the time behind the errors, this window and the earlier ones, at
  /// least kWallHistoryWindows windows' worth (time).
  double history = 0;
  /// Standard errors of P and T (for T none without hits).
  std::optional<double> P_stderr, T_stderr;
};

/// How many windows' worth of run, at the same wall, the error from history needs; it looks
/// back over at most kWallHistoryLimit windows, so a run that is still settling weighs less.
constexpr double kWallHistoryWindows = 4, kWallHistoryLimit = 16;
/// How many intervals a window needs for the error from its own parts: its sixteenths hold
/// four or more each.
constexpr std::size_t kWallPartsIntervals = 64;

/// P and T over the intervals that end in (t_end_last - window, t_end_last] (every interval
/// when window <= 0), with the standard errors a reader can trust at any window length.
///
/// Why not from the window alone: batch means or blocking inside the window assume that its
/// parts become independent once they are long enough, but the wall's readings are regular
/// motion at heart: a particle of an ideal gas hits the wall at fixed intervals, an oscillator
/// twice a period. A window then holds about the same number of hits whatever its phase, the
/// error of its mean falls like 1 / window instead of 1 / sqrt(window), and the parts'
/// spread overstates it (measured: 7x at long windows for J = 0, 4x for J > 0).
///
/// So the error is measured where it is defined: the means of every window of the same length
/// that ends at an interval end in the run's recent history (at most kWallHistoryLimit
/// windows back, all at the wall's present radius), their standard deviation corrected for
/// the overlapping windows' shared mean (overlapping batch means, Meketon and Schmeiser
/// 1984: a variance times H / (H - window) for history H). T's error is that of the
/// hit-weighted mean.
///
/// With less than kWallHistoryWindows windows of history (a run's start, a wall that just
/// moved, the whole run as the window, an ensemble run's averaging window), the window's own
/// parts: the same errors for its quarters and sixteenths, from the history inside the window,
/// and the variance of a part's sum S(w) = w^2 se(w)^2 carried on from a quarter to the whole
/// as w^alpha, alpha measured between the two and held to [0, 1]. Regular motion keeps S
/// bounded (alpha near 0, the error falling like 1 / window); independent parts make it grow
/// like w (alpha 1, like 1 / sqrt(window), as blocking assumes, which overstated J = 0's error
/// 3.5x). Measured against J = 0's exact 2 KE / (3 V): about 0.9x to 1.8x the true error (the
/// more, the shorter the window against the hit period); it cannot see what varies more
/// slowly than a quarter of the window. None with fewer than kWallPartsIntervals intervals.
///
/// Either way the error is that of this run's window about this run's own long-run value, not
/// the spread between runs from other seeds (which differ in energy): an ensemble gives that.
WallEstimate wall_estimate(const std::vector<WallInterval>& intervals, double window);

}  // namespace swarm
