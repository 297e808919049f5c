#include "swarm/integrators.h"

namespace swarm {

void step_verlet(System& s, double dt, int threads) {
  std::vector<Vec3> a;
  pairwise_accelerations(s, a, threads);
  for (std::size_t i = 0; i < s.particles.size(); ++i) {
    auto& p = s.particles[i];
    p.v += a[i] * (0.5 * dt);
    p.r += p.v * dt;
  }
  pairwise_accelerations(s, a, threads);
  for (std::size_t i = 0; i < s.particles.size(); ++i) s.particles[i].v += a[i] * (0.5 * dt);
  s.t += dt;
}

}  // namespace swarm
