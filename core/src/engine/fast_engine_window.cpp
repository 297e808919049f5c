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

}  // namespace

Window window_of(const Vec3& a, const Vec3& b, const Spring& spring, double T2,
                 double phase_origin) {
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

Window always_window(double k) {
  if (k > 0) return {0, 4};
  return {kInf, kInf};
}

}  // namespace swarm::fast
