#pragma once
// An arctangent and a logarithm with a stated error bound, for the fast engine's scheduler.
// libm's atan2, acos and log cost 20 to 60 ns a call, more under Emscripten's musl, and the
// scheduler calls them at every wall hit. The windows built from these values are widened by
// the bounds, so a particle is never checked too late; the engine's results do not depend on
// them, only which steps a particle is looked at.

#include <cmath>
#include <cstdint>
#include <cstring>

namespace swarm::fast {

/// |fast_atan2(y, x) - atan2(y, x)| <= kAtanError radians (measured: 1.0e-8, in
/// tests/fast_math_test.cpp), up to a sign of pi when y is -0.
inline constexpr double kAtanError = 2e-8;

/// |fast_log(x) - log(x)| <= kLogError for finite x > 0 (measured: 1.5e-12).
inline constexpr double kLogError = 1e-11;

inline double fast_atan2(double y, double x) {
  const double ay = std::abs(y), ax = std::abs(x);
  if (ay == 0 && ax == 0) return 0;
  const bool steep = ay > ax;
  const double t = steep ? ax / ay : ay / ax;  // in [0, 1]
  const double u = t * t;
  // atan(t) / t as a polynomial in t^2: a degree-8 Chebyshev fit on [0, 1].
  const double p =
      0.9999999817886557 +
      u * (-0.3333303670929285 +
           u * (0.19991872029264307 +
                u * (-0.14197797795407988 +
                     u * (0.10618370642479312 +
                          u * (-0.07456854838521723 +
                               u * (0.04213762374570251 +
                                    u * (-0.015731249223588546 + u * 0.0027662835283182277)))))));
  double r = t * p;
  if (steep) r = M_PI_2 - r;
  if (x < 0) r = M_PI - r;
  return y < 0 ? -r : r;
}

inline double fast_log(double x) {
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  const int biased_exponent = int(bits >> 52);  // includes the sign bit: x < 0 lands above 0x7ff
  if (biased_exponent == 0 || biased_exponent >= 0x7ff) return std::log(x);
  int e = biased_exponent - 1023;
  bits = (bits & ((std::uint64_t(1) << 52) - 1)) | (std::uint64_t(1023) << 52);
  double m;  // x = 2^e m, m in [1, 2)
  std::memcpy(&m, &bits, sizeof m);
  if (m > M_SQRT2) {
    m *= 0.5;
    ++e;
  }
  // log m = 2 atanh(s), s = (m - 1) / (m + 1); atanh(s) / s as a polynomial in s^2 (a
  // degree-4 Chebyshev fit for |s| <= (sqrt 2 - 1) / (sqrt 2 + 1)).
  const double s = (m - 1) / (m + 1), u = s * s;
  const double p =
      1.0000000000041793 +
      u * (0.33333332623755507 +
           u * (0.20000192334836356 + u * (0.14267525577504317 + u * 0.11808178694153203)));
  return e * M_LN2 + 2 * s * p;
}

}  // namespace swarm::fast
