#pragma once
/// Whether a window of a run is in equilibrium, judged by the physics: the virial balance.
///
/// With the container centred at the origin, G = sum m r.v obeys dG/dt = 2 KE + sum r.F. The
/// springs give sum r.F = -J M sum m |r - R_cm|^2 = -2U (U their potential energy), the wall's
/// radial impulses at |r| = R give -3 P V over time. So over a window [t0, t1]
///   mean(3 P V) - mean(2 KE - 2 U) = -(G(t1) - G(t0)) / (t1 - t0),
/// the imbalance. In equilibrium G only fluctuates and the imbalance falls like 1 / (t1 - t0),
/// below the statistical error of the means; a window that starts while G still carries the
/// start's memory (a gas still flowing out to the wall, a swarm still breathing in) averages a
/// P that is not the equilibrium's, by the imbalance. It holds for the springs and a still,
/// elastic wall alone: outside forces, a floor, moving or hot walls and hard spheres' contacts
/// add their own terms (swarm::virial_balance_applies in run.h says when it applies).
///
/// The imbalance is taken from G itself, -(G(t1) - G(t0)) / (t1 - t0): the memory of the
/// start alone. mean(3 P V) - mean(2 KE - 2 U) equals it but for a small residual: the paper's
/// collision scheme reflects at the start of the step, at |r| = R - s with s between 0 and the
/// step's radial travel, so its wall virial is sum (R - s) |dp|, while 3 P V (P over the area
/// at R) books R |dp|: 3 P V exceeds the wall's virial by about <v_r> dt / (2 R) of itself
/// (measured in virial_balance_test: 5e-4 of 3PV at dt = 0.001 and speeds up to 1.5; 1.7e-4
/// in 12 runs of 40 time units at dt = 0.0005 and speeds up to 1, where counted into the
/// imbalance it made the runs' mean 2.6e-4 [0.3e-4, 4.9e-4], a memory they do not have).
/// That is the scheme's dt systematic, not equilibrium's; the residual shows it, with the
/// trapezoid rule's error in 2 KE - 2 U.

#include <optional>
#include <vector>

namespace swarm {

/// One sample interval's terms (energy units), from a run's samples (virial_intervals, run.h).
struct VirialInterval {
  double t_end = 0, duration = 0;  ///< time
  double wall = 0;  ///< 3 P V over the interval, P the wall's pressure at the radius R it had
  /// 2 KE - 2 U, the mean of its values at the interval's two ends (the trapezoid rule)
  double kinetic = 0;
  double G_start = 0, G_end = 0;  ///< sum m r.v about the container's centre at the ends
};

/// The balance over a window: the means, G at the window's ends, the imbalance and its error.
struct VirialBalance {
  double start = 0, end = 0;  ///< the window (time)
  long intervals = 0;
  double wall = 0;     ///< mean of 3 P V over time
  double kinetic = 0;  ///< mean of 2 KE - 2 U over time
  double G_start = 0, G_end = 0;
  /// -(G_end - G_start) / (end - start), which the identity makes wall - kinetic: how far
  /// the window's mean of 3 P V lies from the one that balances its 2 KE - 2 U because the
  /// window remembers its start.
  double imbalance = 0;
  /// wall - kinetic - imbalance: the collision scheme's and the trapezoid rule's share (see
  /// above), 0 for exact hits and sampling.
  double residual = 0;
  /// The standard error of the imbalance, from G's own spread: sqrt(2 mean(G^2)) / (end -
  /// start), G's mean square over the window (trapezoid). Equilibrium is even in the
  /// velocities (time reversal), so there <G> = 0, and G(t0) and G(t1), once the window
  /// outlasts G's memory, are two independent draws of spread sqrt(<G^2>): their difference
  /// over the window has variance 2 <G^2> / (end - start)^2 (less in a shorter window, where
  /// this errs wide). Blocking 3 P V - (2 KE - 2 U), as P is blocked, errs wide by about the
  /// square root of its number of blocks: the difference is -dG/dt, whose sum over a block
  /// telescopes to the block's ends, so block means spread as 1 / length, not 1 / sqrt(length)
  /// (measured in virial_balance_test: 3x in the held-out gas, where blocking flags
  /// 1 of 16 windows that start while the gas still breathes, G's spread 13). G's mean square
  /// about 0 counts a memory still in the window as spread, so it errs wide there too, and in
  /// a window that is all memory (a run of 1 time unit, the first outflow to the wall) wider
  /// than blocking. Both err wide, never narrow, so the error is the smaller of the two; in
  /// equilibrium that is G's. Windows from the middle of long runs are flagged about as often
  /// as |z| > 2 should, 5 %, a little more for an ideal gas, whose breathing only dephases
  /// (60 seeds of J = +-1 / M, 200 particles over 20 time units: 5 and 3 of 60, rms
  /// imbalance / error 1.08 and 0.98; J = 0 over 40: 7 of 60, rms 1.14; with 300 particles
  /// at dt = 0.0005, 1 of 30, rms 0.9); their runs' chosen starts none (0 of 180).
  double error = 0;
  /// |imbalance| <= kVirialBalanceErrors errors: the window's memory of its start is below
  /// the statistical error of its means.
  bool holds = false;
  /// The imbalance relative to 3 P V: the fraction by which the window's P is off the value
  /// that balances (0 when 3 P V is 0).
  double relative() const { return wall != 0 ? imbalance / wall : 0; }
};

/// How many standard errors the imbalance may be within to hold (about 95 %).
constexpr double kVirialBalanceErrors = 2;

/// The balance over the intervals that end after `from` (each interval whole, from the first
/// that starts at or after `from`); none with fewer than 8 of them, the same as a P in
/// wall_time_averages.
std::optional<VirialBalance> virial_balance(const std::vector<VirialInterval>& intervals,
                                            double from);

}  // namespace swarm
