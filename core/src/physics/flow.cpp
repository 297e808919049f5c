#include "swarm/physics/flow.h"

#include "math/portable_math.h"
#include "swarm/physics/regime.h"

namespace swarm {

Flow Flow::over(double k, double t) {
  const double w = omega_of(k);
  switch (regime_of(k)) {
    case Regime::attractive: {
      // The core's own functions, so that native and WebAssembly runs agree to the bit.
      double sin_wt, cos_wt;
      portable::sincos(w * t, &sin_wt, &cos_wt);
      return {cos_wt, sin_wt / w, k};
    }
    case Regime::repulsive:
      return {portable::cosh(w * t), portable::sinh(w * t) / w, k};
    case Regime::free:
      break;
  }
  return {1.0, t, 0.0};
}

}  // namespace swarm
