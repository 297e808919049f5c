#include "swarm/methods/integrators.h"
#include "swarm/physics/flow.h"
#include "swarm/physics/regime.h"

namespace swarm {

void step_analytic(System& s, double dt, int /*threads: one pass, O(N)*/) {
  // The CM is recomputed from the particles every step rather than carried separately: in the
  // repulsive case any difference between the two would grow as exp(Omega t).
  const Vec3 R = cm_position(s);
  const Vec3 V = cm_velocity(s);
  const Flow f = Flow::over(stiffness(s), dt);
  const Vec3 R_next = R + V * dt;
  for (auto& p : s.particles) {
    const Vec3 x = p.r - R;
    const Vec3 u = p.v - V;
    p.r = R_next + f.c * x + f.s * u;
    p.v = V + f.dc() * x + f.c * u;
  }
  s.t += dt;
}

}  // namespace swarm
