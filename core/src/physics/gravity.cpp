#include "swarm/physics/gravity.h"

namespace swarm {

double gravity_potential_energy(const System& s, const Vec3& g) {
  double u = 0;
  for (const auto& p : s.particles) u -= p.m * g.dot(p.r);
  return u;
}

}  // namespace swarm
