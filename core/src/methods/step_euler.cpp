#include "swarm/methods/external_forces.h"
#include "swarm/methods/integrators.h"

namespace swarm {

void step_euler(System& s, double dt, int threads, const ExternalForces& f) {
  std::vector<Vec3> a;
  accelerations(s, f, a, threads);
  for (std::size_t i = 0; i < s.particles.size(); ++i) {
    auto& p = s.particles[i];
    p.r += p.v * dt;
    p.v += a[i] * dt;
  }
  s.t += dt;
}

void step_euler(System& s, double dt, int threads) { step_euler(s, dt, threads, {}); }

}  // namespace swarm
