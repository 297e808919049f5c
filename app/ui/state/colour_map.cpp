#include "ui/state/colour_map.h"

#include <algorithm>
#include <cmath>

#include "access/theme_palette.h"
#include "i18n/translator.h"

namespace swarmlab {

const char* legend_title(ColourBy c) {
  switch (c) {
    case ColourBy::speed:
      return tr("speed |v|  (length/time)");
    case ColourBy::mass:
      return tr("mass m");
    case ColourBy::energy:
      return tr("energy \u00bd m v\u00b2 + \u00bd J M m |r \u2212 R|\u00b2");
  }
  return "";
}

Rgba8 turbo(float x, std::uint8_t alpha) {
  Colour c = turbo_colour(x);
  c.a = alpha;
  return c.packed();
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
