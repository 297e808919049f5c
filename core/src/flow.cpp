#include "swarm/flow.h"

#include <cmath>

#include "swarm/regime.h"

namespace swarm {

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
