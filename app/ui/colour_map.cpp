#include "colour_map.h"

#include <algorithm>
#include <cmath>

namespace swarmlab {

const char* legend_title(ColourBy c) {
  switch (c) {
    case ColourBy::speed:
      return "speed |v|  (length/time)";
    case ColourBy::mass:
      return "mass m";
    case ColourBy::energy:
      return "energy \u00bd m v\u00b2 + \u00bd J M m |r \u2212 R|\u00b2";
  }
  return "";
}

Rgba8 turbo(float x, std::uint8_t alpha) {
  // Polynomial fit of the Turbo map (Mikhailov, Google AI blog, 2019), kept away from its
  // darkest ends.
  const double t = 0.06 + 0.9 * std::clamp(double(x), 0.0, 1.0);
  const double t2 = t * t, t3 = t2 * t, t4 = t3 * t, t5 = t4 * t;
  const double r = 0.13572138 + 4.61539260 * t - 42.66032258 * t2 + 132.13108234 * t3 -
                   152.94239396 * t4 + 59.28637943 * t5;
  const double g = 0.09140261 + 2.19418839 * t + 4.84296658 * t2 - 14.18503333 * t3 +
                   4.27729857 * t4 + 2.82956604 * t5;
  const double b = 0.10667330 + 12.64194608 * t - 60.58204836 * t2 + 110.36276771 * t3 -
                   89.90310912 * t4 + 27.34824973 * t5;
  auto byte = [](double c) { return Rgba8(std::lround(std::clamp(c, 0.0, 1.0) * 255.0)); };
  return byte(r) | byte(g) << 8 | byte(b) << 16 | Rgba8(alpha) << 24;
}

double ParticleQuantity::operator()(const swarm::Particle& p) const {
  switch (by) {
    case ColourBy::speed:
      return p.v.norm();
    case ColourBy::mass:
      return p.m;
    case ColourBy::energy:
      return 0.5 * p.m * p.v.squaredNorm() + 0.5 * stiffness * p.m * (p.r - cm).squaredNorm();
  }
  return 0;
}

void ColourScale::follow(double data_lo, double data_hi) {
  if (!(data_hi > data_lo)) {
    // One value (equal masses, one particle): centre it in a unit-wide range.
    const double mid = std::isfinite(data_lo) ? data_lo : 0.0;
    const double half = std::max(std::abs(mid) * 0.5, 1e-12);
    data_lo = mid - half;
    data_hi = mid + half;
  }
  if (locked && initialised) return;
  if (!initialised) {
    lo = data_lo;
    hi = data_hi;
    initialised = true;
    return;
  }
  // Widen at once, narrow slowly: a particle faster than the scale never saturates for long.
  lo = data_lo < lo ? data_lo : lo + 0.05 * (data_lo - lo);
  hi = data_hi > hi ? data_hi : hi + 0.05 * (data_hi - hi);
}

float ColourScale::position(double value) const {
  return hi > lo ? float((value - lo) / (hi - lo)) : 0.5f;
}

}  // namespace swarmlab
