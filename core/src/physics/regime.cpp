#include "swarm/physics/regime.h"

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
  return k > 0 ? natural_time_of(k) : std::numeric_limits<double>::infinity();
}

double natural_time_of(double k) {
  if (k == 0) return std::numeric_limits<double>::infinity();
  return 2 * M_PI / omega_of(k);
}

}  // namespace swarm
