#pragma once
/// The forces from outside the swarm (gravity, drag) and how each method steps a system under
/// them. With no external force every method takes its own step unchanged, to the bit.

#include <optional>

#include "swarm/methods/method.h"
#include "swarm/physics/drag.h"
#include "swarm/physics/system.h"

namespace swarm {

struct ExternalForces {
  Vec3 gravity = Vec3::Zero();  ///< uniform acceleration g on every particle (length/time^2)
  std::optional<Drag> drag;

  bool any() const { return gravity != Vec3::Zero() || drag.has_value(); }
};

/// The exact map over a time t of a swarm under gravity g and mass-proportional drag gamma,
/// whose motion about the CM obeys x'' = -k x - gamma x' (k = J M):
///   about the CM:  x(t) = xc x0 + xs u0,   u(t) = vc x0 + vs u0;
///   the CM:        R(t) = R0 + cm_v V0 + cm_g g,   V(t) = cm_vv V0 + cm_vg g.
/// gamma = 0 gives the undamped Flow and free fall (cm_v = t, cm_g = t^2 / 2). For gamma > 0
/// the regime follows k - gamma^2 / 4: under-damped (> 0), critical (= 0), over-damped or, for
/// J < 0, a damped runaway (< 0).
struct ForcedFlow {
  double xc = 1, xs = 0, vc = 0, vs = 1;
  double cm_v = 0, cm_g = 0, cm_vv = 1, cm_vg = 0;

  static ForcedFlow over(double k, double gamma, double t);
};

/// One step of method m under the forces. The analytic method needs mass-proportional drag (or
/// none). Returns the energy the drag took in the step: exactly the drop of the energy for the
/// analytic map (which is exact), the trapezoidal rule on the drag power for the others.
double step_with_forces(Method m, System& s, double dt, int threads, const ExternalForces& f);

/// The exact step of the analytic method under gravity and mass-proportional drag.
void step_analytic_forced(System& s, double dt, const ExternalForces& f);

/// The pairwise accelerations (eq. 1) plus gravity and the drag's -c_i v_i: what the numerical
/// methods integrate. With no external force, exactly pairwise_accelerations.
void accelerations(const System& s, const ExternalForces& f, std::vector<Vec3>& a, int threads);

}  // namespace swarm
