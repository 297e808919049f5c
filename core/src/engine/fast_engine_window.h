#pragma once
// Closed-form wall windows of a free oscillator, used by the fast engine's scheduler.

#include <cmath>
#include <cstdint>
#include <limits>

#include "swarm/physics/flow.h"
#include "swarm/physics/system.h"

namespace swarm::fast {

/// The times at which a free oscillator h(tau) = c(tau) a + s(tau) b (Flow::over(k, tau))
/// is at least sqrt(T2) from the origin, in two numbers, widened to cover their own rounding.
/// tau counts from the start of the oscillator's epoch, which began at time t0; the numbers
/// are given in time counted from 0, so that they stay valid when the engine starts a new
/// epoch for the same motion. phase_origin is t0 in the numbers' units: 2 sqrt|k| t0 when
/// J != 0, t0 when J = 0.
/// J > 0: |h|^2 = P + A cos(2 omega tau - phi), so the window is |2 omega tau - phi| <= alpha
///        modulo 2 pi (first = phi, second = alpha; alpha < 0: never, alpha >= pi: always).
/// J < 0: E (|h|^2 - T2) is a quadratic in E = exp(2 Omega tau) with positive leading
///        coefficient: the window is E <= E- or E >= E+, i.e. 2 Omega tau <= first = log E-
///        or >= second = log E+.
/// J = 0: |h|^2 - T2 is a quadratic in tau: the window is tau <= first or tau >= second.
/// An orbit about a point off the origin (off_centre_window_of) may reach the wall at one end
/// of its ellipse only: its J > 0 window can open once a turn, |2 omega tau - first| <= second
/// - kOnceATurn modulo 4 pi, which second >= kOnceATurn says.
/// Under mass-proportional drag gamma = 2 eta the oscillator is h = exp(-eta tau) u, u the free
/// one of stiffness k - eta^2 with coefficients a and b + eta a (ForcedFlow); exp(-eta tau) only
/// decays, so from the window's making at tau0 on, |h|^2 >= T2 needs |u|^2 >= T2 exp(2 eta
/// tau0): u's window for that threshold holds h's, and the cases above are those of k - eta^2.
struct Window {
  double first = 0, second = 0;
};

/// The oscillator's k = J M and 1 / sqrt|k| (0 when k = 0); under drag gamma, eta = gamma / 2
/// and k the damped stiffness J M - eta^2.
struct Spring {
  double k = 0, inv_omega = 0, eta = 0;
};

/// For J > 0, with B = b / omega and theta = omega tau:
/// |h|^2 = P + Q cos(2 theta) + S sin(2 theta) = P + A cos(2 theta - phi), so |h| swings
/// between sqrt(P - A) and sqrt(P + A).
struct Swing {
  double P, Q, S, A;
};

inline Swing swing_of(const Vec3& a, const Vec3& b, double inv_omega) {
  const Vec3 B = b * inv_omega;
  const double aa = a.squaredNorm(), BB = B.squaredNorm();
  const double Q = 0.5 * (aa - BB), S = a.dot(B);
  return {0.5 * (aa + BB), Q, S, std::sqrt(Q * Q + S * S)};
}

/// growth: exp(2 eta tau0) under drag (tau0: now, in the epoch's time), else 1.
Window window_of(const Vec3& a, const Vec3& b, const Spring& spring, double T2,
                 double phase_origin, double growth = 1);

/// The tag a J > 0 window that opens once a turn carries in Window::second (see Window).
inline constexpr double kOnceATurn = 16;

/// The times at which h(tau) + w, an orbit about the point w, is at least sqrt(T2) from the
/// origin (without drag), in window_of's numbers: where a swarm that sits off the container's
/// centre (under gravity) reaches the wall. With x = h(tau), |x + w|^2 = |x|^2 + 2 w.x + |w|^2:
/// J > 0: with theta = omega tau, |x|^2 = P + A cos(2 theta - phi) <= P + A and w.x = rho
///        cos(theta - psi), so the window lies within both
///          S1: |x| >= sqrt(T2) - |w|                       (twice a turn, as window_of's), and
///          S2: cos(theta - psi) >= (T2 - P - A - |w|^2) / (2 rho)   (once a turn, about psi):
///        never where either is. Else |x + w|^2 - T2, a sum of sinusoids in theta and 2 theta,
///        is evaluated on a grid of the turn, finer where the arc ends, and the bound of its
///        second derivative between grid points says where it can reach 0: the window is the
///        arc over those places (once a turn, open a grid step or two before and after the
///        crossings: 2 pi / 128 in theta), or S1 where that is open for less time. (S1 and S2's
///        common part alone held windows open far longer under gravity, where the anchors'
///        centres are 0.6 to 1.3 R out and S2 often holds all round: 1,527 checks a step
///        against 594 at N = 40,000, bench/RESULTS.md.)
/// J = 0: |x + w| is the distance of a straight line: window_of's for a + w.
/// J < 0: S1 alone.
Window off_centre_window_of(const Vec3& a, const Vec3& b, const Vec3& w, const Spring& spring,
                            double T2, double phase_origin);
/// off_centre_window_of with its grid of the turn four points to an AVX2 register, to the
/// last bit (the scalar one where the build has no AVX2 path). Only on a CPU with AVX2:
/// off_centre_windows_of (fast_engine_window_batch.h) asks.
Window off_centre_window_of_avx2(const Vec3& a, const Vec3& b, const Vec3& w,
                                 const Spring& spring, double T2, double phase_origin);

/// The times at which one coordinate of the oscillator, h_z(tau) = xc(tau) a_z + xs(tau) b_z,
/// can be at or below the level L: a floor's window, in the same two numbers as window_of's
/// but in phases of half the size (sqrt|k| t when J != 0, t when J = 0: floor_clock).
/// J > 0: h_z = A cos(omega tau - phi), at most L where |omega tau - phi - pi| <= alpha.
/// J < 0: with u = exp(Omega tau), u (h_z - L) is a quadratic in u; where it is at most 0
///        between two roots, the window is taken from the first root on (a superset).
/// J = 0: h_z is linear in tau.
/// Under drag (Spring::eta), as in window_of, for L < 0 the free oscillation's window for the
/// level L sqrt(growth) holds the damped one's from now on; for L >= 0 the window is always.
Window floor_window_of(double a_z, double b_z, const Spring& spring, double L, double phase_origin,
                       double growth = 1);

/// The window of a motion that is at least sqrt(T2) from the origin at all times (T2 <= 0).
Window always_window(double k);
/// A window that never opens (no wall).
Window never_window(double k);

/// The time from which a schedule looks for the window: the end of a step, counted from 0.
/// The windows' phase is phase_per_time * time: 2 sqrt|k| t when J != 0, t itself when J = 0.
struct Clock {
  double k = 0, phase_per_time = 1;
  double steps_per_phase = 0;  ///< 1 / (phase_per_time dt)
  double time = 0;
};

/// The clock of floor windows for a wall clock: half the phase per time when J != 0.
inline Clock floor_clock(Clock clock) {
  if (clock.k != 0) {
    clock.phase_per_time *= 0.5;
    clock.steps_per_phase *= 2;
  }
  return clock;
}

/// Where the window lies, in steps after the clock's step: it begins `begin` steps after it
/// (0: it already has; +infinity: never) and ends `end` steps after it (+infinity: it lasts).
/// Not rounded: the caller rounds begin down and end up, with a safety margin.
struct Span {
  double begin = 0, end = 0;
};

inline Span span_of(const Window& w, const Clock& clock) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  constexpr double kTwoPi = 2 * M_PI;
  if (clock.k > 0) {
    const double phi = w.first;
    double alpha = w.second, period = kTwoPi, per_period = 1 / kTwoPi;
    if (alpha < 0) return {kInf, kInf};
    if (alpha >= kOnceATurn) {
      alpha -= kOnceATurn;
      period = 2 * kTwoPi;
      per_period = 1 / (2 * kTwoPi);
    } else if (alpha >= M_PI) {
      return {0, kInf};
    }
    const double x = clock.phase_per_time * clock.time - phi;
    // x minus the nearest multiple of the period, in [-period / 2, period / 2] (|x| stays far
    // below 2^53).
    const double turns = x * per_period;
    const double psi = x - period * double(std::int64_t(turns + (turns >= 0 ? 0.5 : -0.5)));
    if (std::abs(psi) <= alpha) return {0, (alpha - psi) * clock.steps_per_phase};
    const double ahead = psi > alpha ? period - alpha - psi : -alpha - psi;
    return {ahead * clock.steps_per_phase, (ahead + 2 * alpha) * clock.steps_per_phase};
  }
  // J <= 0: the window is x <= first or x >= second.
  const double x = clock.phase_per_time * clock.time;
  if (x <= w.first) return {0, (w.first - x) * clock.steps_per_phase};
  if (x >= w.second) return {0, kInf};
  return {(w.second - x) * clock.steps_per_phase, kInf};  // +infinity when second is
}

}  // namespace swarm::fast
