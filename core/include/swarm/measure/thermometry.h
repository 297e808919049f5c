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

/// P and T over a trailing window, as numbers to read off with their uncertainty.
struct WallEstimate {
  WallReading mean;   ///< the wall_average over the window's intervals
  double window = 0;  ///< the time those intervals cover
  int intervals = 0;  ///< how many intervals the window holds
  int blocks = 0;     ///< sub-windows the uncertainty was estimated from
  /// Standard errors of P and T from batch means (below); none with fewer than two
  /// sub-windows (for T: with hits).
  std::optional<double> P_stderr, T_stderr;
};

/// P and T over the intervals that end in (t_end_last - window, t_end_last] (every interval
/// when window <= 0), with standard errors by batch means: the window is cut into `blocks`
/// sub-windows of equal time (fewer when it holds fewer intervals), each interval going to
/// the sub-window its end falls in; each sub-window's wall_average is one batch value, and the
/// standard error is the standard deviation of the batch values (n - 1 in the denominator)
/// over sqrt(n). For T only sub-windows with hits count. Batches are only as independent as
/// they are long: sub-windows shorter than the time the wall readings stay correlated (about
/// a period) understate the error.
WallEstimate wall_estimate(const std::vector<WallInterval>& intervals, double window,
                           int blocks = 8);

}  // namespace swarm
