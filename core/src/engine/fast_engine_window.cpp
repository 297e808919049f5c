#include "engine/fast_engine_window.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "math/fast_math.h"

namespace swarm::fast {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

Window attractive(const Vec3& a, const Vec3& b, double inv_omega, double T2) {
  const auto [P, Q, S, A] = swing_of(a, b, inv_omega);
  if (T2 <= P - A) return {0, 4};  // always at least sqrt(T2) from the origin
  if (T2 > P + A) return {0, -1};  // never
  // alpha = acos(cos_alpha); phi and alpha may each be off by kAtanError.
  const double cos_alpha = (T2 - P) / A;
  const double sin_alpha = std::sqrt(std::max(0.0, (1 - cos_alpha) * (1 + cos_alpha)));
  return {fast_atan2(S, Q), fast_atan2(sin_alpha, cos_alpha) + 2 * kAtanError};
}

Window repulsive(const Vec3& a, const Vec3& b, double inv_omega, double T2) {
  // h = C e^{Omega tau} + D e^{-Omega tau}; with E = e^{2 Omega tau},
  // E (|h|^2 - T2) = cc E^2 + beta E + dd, beta = 2 C.D - T2.
  const Vec3 bW = b * inv_omega;
  const Vec3 C = 0.5 * (a + bW), D = 0.5 * (a - bW);
  const double cc = C.squaredNorm(), dd = D.squaredNorm(), beta = 2 * C.dot(D) - T2;
  const double disc = beta * beta - 4 * cc * dd;
  if (beta >= 0 || disc <= 0) return {kInf, kInf};               // never negative for E > 0: always
  if (cc <= 0) return {fast_log(-dd / beta) + kLogError, kInf};  // only the decaying part
  // beta < 0, so neither root suffers cancellation.
  const double q = -beta + std::sqrt(disc);
  const double E_plus = q / (2 * cc), E_minus = 2 * dd / q;
  return {fast_log(E_minus) + kLogError, fast_log(E_plus) - kLogError};
}

Window free(const Vec3& a, const Vec3& b, double T2) {
  const double aa = a.squaredNorm(), ab = a.dot(b), bb = b.squaredNorm();
  if (bb <= 0) return aa >= T2 ? Window{kInf, kInf} : Window{-kInf, kInf};
  const double disc = ab * ab - bb * (aa - T2);
  if (disc <= 0) return {kInf, kInf};
  const double root = std::sqrt(disc);
  // One root without cancellation, the other from the product of the roots.
  if (ab <= 0) {
    const double tau_plus = (-ab + root) / bb;
    return {(aa - T2) / (bb * tau_plus), tau_plus};
  }
  const double tau_minus = (-ab - root) / bb;
  return {tau_minus, (aa - T2) / (bb * tau_minus)};
}

// A window that opens once a turn: an arc of half-width h about c, in phases of 2 theta.
Window once_a_turn(double c, double h) {
  if (h >= 2 * M_PI) return {0, 4};  // always
  return {c, kOnceATurn + h};
}

// x + w with x = a cos(theta) + B sin(theta), B = b / omega: the common part of S1 and S2
// (fast_engine_window.h), in phases of 2 theta.
Window attractive_off_centre(const Vec3& a, const Vec3& b, const Vec3& w, double inv_omega,
                             double T2) {
  const double w2 = w.squaredNorm();
  const double inner = std::sqrt(T2) - std::sqrt(w2);
  const Window s1 = inner > 0 ? attractive(a, b, inv_omega, inner * inner) : Window{0, 4};
  if (s1.second < 0) return s1;  // never
  const Vec3 B = b * inv_omega;
  const auto [P, Q, S, A] = swing_of(a, b, inv_omega);
  const double u = w.dot(a), v = w.dot(B), rho = std::sqrt(u * u + v * v);
  // S2: 2 rho cos(theta - psi) >= need, with need lowered by far more than its rounding.
  const double sum = T2 + P + A + w2;
  const double need = T2 - P - A - w2 - 1e-12 * sum;
  if (need <= -2 * rho) return s1;  // S2 always (also when rho = 0 and need <= 0)
  if (need > 2 * rho) return {0, -1};
  const double cos_beta = need / (2 * rho);
  const double sin_beta = std::sqrt(std::max(0.0, (1 - cos_beta) * (1 + cos_beta)));
  // S2 is the arc |2 theta - c2| <= h2 modulo 4 pi; c2 and the half-width are each off by
  // 2 kAtanError at most.
  const double c2 = 2 * fast_atan2(v, u);
  const double h2 = 2 * fast_atan2(sin_beta, cos_beta) + 4 * kAtanError;
  if (s1.second >= M_PI) return once_a_turn(c2, h2);  // S1 always
  // S1's arcs lie about phi + 2 pi j, of half-width alpha; the nearest to c2 is |d| from it,
  // the next 2 pi - |d| >= |d|.
  constexpr double kTwoPi = 2 * M_PI;
  const double phi = s1.first, alpha = s1.second;
  const double turns = (c2 - phi) * (1 / kTwoPi);
  const double d =
      c2 - phi - kTwoPi * double(std::int64_t(turns + (turns >= 0 ? 0.5 : -0.5)));
  if (std::abs(d) > alpha + h2) return {0, -1};  // S2 meets neither arc
  const double near = c2 - d;
  double lo = std::max(c2 - h2, near - alpha), hi = std::min(c2 + h2, near + alpha);
  if (kTwoPi - std::abs(d) <= alpha + h2) {  // and the other arc too: the arc over both parts
    const double far = near + (d >= 0 ? kTwoPi : -kTwoPi);
    lo = std::min(lo, std::max(c2 - h2, far - alpha));
    hi = std::max(hi, std::min(c2 + h2, far + alpha));
  }
  // S1 is open 4 alpha of every 4 pi; the arc hi - lo. The arc's ends carry the rounding of
  // c2 - phi's reduction and of their sums, far below 1e-12.
  if (hi - lo >= 4 * alpha) return s1;
  return once_a_turn(0.5 * (lo + hi), 0.5 * (hi - lo) + 1e-12);
}

// h_z = A cos(theta - phi) <= L: |theta - phi - pi| <= alpha, cos alpha = -L / A.
Window attractive_floor(double a_z, double b_z, double inv_omega, double L) {
  const double B = b_z * inv_omega;
  const double A = std::sqrt(a_z * a_z + B * B);
  if (L >= A) return {0, 4};    // always at or below L
  if (L < -A) return {0, -1};  // never
  const double cos_alpha = -L / A;
  const double sin_alpha = std::sqrt(std::max(0.0, (1 - cos_alpha) * (1 + cos_alpha)));
  return {fast_atan2(B, a_z) + M_PI, fast_atan2(sin_alpha, cos_alpha) + 2 * kAtanError};
}

// h_z = C u + D / u, u = exp(Omega tau): h_z <= L where q(u) = C u^2 - L u + D <= 0.
Window repulsive_floor(double a_z, double b_z, double inv_omega, double L) {
  const double bW = b_z * inv_omega;
  const double C = 0.5 * (a_z + bW), D = 0.5 * (a_z - bW);
  const auto log_of = [](double u) { return u > 0 ? fast_log(u) : -kInf; };
  if (C == 0) {
    if (L > 0) return {-kInf, log_of(D / L) - kLogError};  // u >= D / L
    if (L < 0) return {D / L > 0 ? log_of(D / L) + kLogError : -kInf, kInf};  // u <= D / L
    return D <= 0 ? Window{kInf, kInf} : Window{-kInf, kInf};
  }
  const double disc = L * L - 4 * C * D;
  if (disc < 0) return C > 0 ? Window{-kInf, kInf} : Window{kInf, kInf};
  // The roots without cancellation: one from the quadratic formula, the other from their
  // product D / C.
  const double q = 0.5 * (L + std::copysign(std::sqrt(disc), L));
  const double r1 = q / C, r2 = q != 0 ? D / q : 0.0;
  const double lo = std::min(r1, r2), hi = std::max(r1, r2);
  if (C > 0) return {-kInf, hi <= 0 ? kInf : log_of(lo) - kLogError};  // lo <= u <= hi
  return {lo > 0 ? log_of(lo) + kLogError : -kInf, log_of(hi) - kLogError};  // u <= lo, u >= hi
}

// h_z = a_z + b_z tau <= L.
Window free_floor(double a_z, double b_z, double L) {
  if (b_z == 0) return a_z <= L ? Window{kInf, kInf} : Window{-kInf, kInf};
  const double tau = (L - a_z) / b_z;
  return b_z > 0 ? Window{tau, kInf} : Window{-kInf, tau};
}

}  // namespace

Window floor_window_of(double a_z, double b_free_z, const Spring& spring, double L_now,
                       double phase_origin, double growth) {
  const bool damped = spring.eta != 0;
  if (damped && L_now >= 0) return always_window(spring.k);
  const double b_z = damped ? b_free_z + spring.eta * a_z : b_free_z;
  const double L = damped ? L_now * std::sqrt(growth) : L_now;
  const double rounding = 4 * std::numeric_limits<double>::epsilon() * (std::abs(phase_origin) + 8);
  if (spring.k > 0) {
    const Window w = attractive_floor(a_z, b_z, spring.inv_omega, L);
    return {w.first + phase_origin,
            w.second < 0 || w.second >= M_PI ? w.second : w.second + rounding};
  }
  const Window w =
      spring.k < 0 ? repulsive_floor(a_z, b_z, spring.inv_omega, L) : free_floor(a_z, b_z, L);
  return {w.first + phase_origin + rounding, w.second + phase_origin - rounding};
}

Window window_of(const Vec3& a, const Vec3& b_free, const Spring& spring, double T2_now,
                 double phase_origin, double growth) {
  const bool damped = spring.eta != 0;
  const Vec3 b = damped ? Vec3(b_free + spring.eta * a) : b_free;
  const double T2 = damped ? T2_now * growth : T2_now;
  // Each phase moves by the origin's; its rounding widens the window.
  const double rounding = 4 * std::numeric_limits<double>::epsilon() * (std::abs(phase_origin) + 8);
  if (spring.k > 0) {
    const Window w = attractive(a, b, spring.inv_omega, T2);
    return {w.first + phase_origin,
            w.second < 0 || w.second >= M_PI ? w.second : w.second + rounding};
  }
  const Window w = spring.k < 0 ? repulsive(a, b, spring.inv_omega, T2) : free(a, b, T2);
  return {w.first + phase_origin + rounding, w.second + phase_origin - rounding};
}

Window off_centre_window_of(const Vec3& a, const Vec3& b, const Vec3& w, const Spring& spring,
                            double T2, double phase_origin) {
  if (spring.k == 0) return window_of(a + w, b, spring, T2, phase_origin);  // exact
  if (spring.k < 0) {
    const double inner = std::sqrt(T2) - w.norm();
    return inner > 0 ? window_of(a, b, spring, inner * inner, phase_origin)
                     : always_window(spring.k);
  }
  const Window win = attractive_off_centre(a, b, w, spring.inv_omega, T2);
  if (win.second < 0 || (win.second >= M_PI && win.second < kOnceATurn)) return win;
  const double rounding = 4 * std::numeric_limits<double>::epsilon() * (std::abs(phase_origin) + 8);
  return {win.first + phase_origin, win.second + rounding};
}

Window always_window(double k) {
  if (k > 0) return {0, 4};
  return {kInf, kInf};
}

Window never_window(double k) {
  if (k > 0) return {0, -1};
  return {-kInf, kInf};
}

}  // namespace swarm::fast
