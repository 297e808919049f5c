#include "swarm/regime.h"

#include <cmath>
#include <limits>

namespace swarm {

Regime regime_of(double k) {
  if (k > 0) return Regime::attractive;
  if (k < 0) return Regime::repulsive;
  return Regime::free;
}

double omega_of(double k) { return std::sqrt(std::abs(k)); }

double period_of(double k) {
  if (k > 0) return 2 * M_PI / std::sqrt(k);
  return std::numeric_limits<double>::infinity();
}

Flow Flow::over(double k, double t) {
  const double w = omega_of(k);
  switch (regime_of(k)) {
    case Regime::attractive:
      return {std::cos(w * t), std::sin(w * t) / w, k};
    case Regime::repulsive:
      return {std::cosh(w * t), std::sinh(w * t) / w, k};
    case Regime::free:
      break;
  }
  return {1.0, t, 0.0};
}

}  // namespace swarm
