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

}  // namespace swarm
