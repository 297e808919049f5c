#include "swarm/integrators.h"

namespace swarm {

void step_euler(System& s, double dt, int threads) {
  std::vector<Vec3> a;
  pairwise_accelerations(s, a, threads);
  for (std::size_t i = 0; i < s.particles.size(); ++i) {
    auto& p = s.particles[i];
    p.r += p.v * dt;
    p.v += a[i] * dt;
  }
  s.t += dt;
}

}  // namespace swarm
