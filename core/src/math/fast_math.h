#pragma once
// An arctangent and a logarithm with a stated error bound, for the fast engine's scheduler.
// libm's atan2, acos and log cost 20 to 60 ns a call, more under Emscripten's musl, and the
// scheduler calls them at every wall hit. The windows built from these values are widened by
// the bounds, so a particle is never checked too late; the engine's results do not depend on
// them, only which steps a particle is looked at.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace swarm::fast {

/// |fast_atan2(y, x) - atan2(y, x)| <= kAtanError radians (measured: 1.0e-8, in
/// tests/core/math/fast_math_test.cpp), 
inline constexpr double kAtanError = 2e-8;

/// |fast_log(x) - log(x)| <= kLogError for finite x > 0 (measured: 1.5e-12).
inline constexpr double kLogError = 1e-11;

inline double fast_atan2(double y, double x) {
  const double ay = std::abs(y), ax = std::abs(x);
  if (ay == 0 && ax == 0) return 0;
  // The octant by arithmetic rather than branches, which the scheduler's data would mispredict.
  const bool steep = ay > ax;
  const double t = std::min(ax, ay) / std::max(ax, ay);  // in [0, 1]
  const double u = t * t;
  // atan(t) / t as a polynomial in t^2: a degree-8 Chebyshev fit on [0, 1], evaluated by
  // Estrin's scheme, whose short dependency chain matters more here than its extra multiply.
  const double u2 = u * u, u4 = u2 * u2;
  const double p01 = 0.9999999817886557 + u * -0.3333303670929285;
  const double p23 = 0.19991872029264307 + u * -0.14197797795407988;
  const double p45 = 0.10618370642479312 + u * -0.07456854838521723;
  const double p67 = 0.04213762374570251 + u * -0.015731249223588546;
  const double p = (p01 + u2 * p23) + u4 * ((p45 + u2 * p67) + u4 * 0.0027662835283182277);
  const double r0 = t * p;
  const double r1 = double(steep) * M_PI_2 + (1 - 2 * double(steep)) * r0;
  const double r = double(x < 0) * M_PI + (1 - 2 * double(x < 0)) * r1;
  return std::copysign(r, y);
}

inline double fast_log(double x) {
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  const int biased_exponent = int(bits >> 52);  // includes the sign bit: x < 0 lands above 0x7ff
  if (biased_exponent == 0 || biased_exponent >= 0x7ff) return std::log(x);
  // x = 2^e m with m in [sqrt(1/2), sqrt 2), without a branch (as musl's log does it): the
  // exponent is taken relative to the bits of sqrt(1/2).
  constexpr std::uint64_t kSqrtHalfBits = 0x3fe6a09e667f3bcd;
  const std::uint64_t relative = bits - kSqrtHalfBits;
  const int e = int(std::int64_t(relative) >> 52);
  const std::uint64_t m_bits = bits - (relative & (std::uint64_t(0xfff) << 52));
  double m;
  std::memcpy(&m, &m_bits, sizeof m);
  // log m = 2 atanh(s), s = (m - 1) / (m + 1); atanh(s) / s as a polynomial in s^2 (a
  // degree-4 Chebyshev fit for |s| <= (sqrt 2 - 1) / (sqrt 2 + 1)), by Estrin's scheme.
  const double s = (m - 1) / (m + 1), u = s * s, u2 = u * u;
  const double p = (1.0000000000041793 + u * 0.33333332623755507) +
                   u2 * ((0.20000192334836356 + u * 0.14267525577504317) + u2 * 0.11808178694153203);
  return e * M_LN2 + 2 * s * p;
}

}  // namespace swarm::fast
