#include "swarm/methods/external_forces.h"
#include "swarm/methods/integrators.h"

namespace swarm {

void step_verlet(System& s, double dt, int threads, const ExternalForces& f) {
  std::vector<Vec3> a;
  accelerations(s, f, a, threads);
  for (std::size_t i = 0; i < s.particles.size(); ++i) {
    auto& p = s.particles[i];
    p.v += a[i] * (0.5 * dt);
    p.r += p.v * dt;
  }
  if (!f.drag) {
    accelerations(s, f, a, threads);
    for (std::size_t i = 0; i < s.particles.size(); ++i) s.particles[i].v += a[i] * (0.5 * dt);
  } else {
    // The closing half kick v1 = v_half + dt/2 (a(x1) - c v1) solved for v1: the drag enters
    // at both ends of the step (trapezoidal), as the forces of position do, so the step stays
    // second order and symmetric.
    ExternalForces without_drag = f;
    without_drag.drag.reset();
    accelerations(s, without_drag, a, threads);
    const std::vector<double> c = drag_rates(*f.drag, s);
    for (std::size_t i = 0; i < s.particles.size(); ++i) {
      auto& p = s.particles[i];
      p.v = (p.v + a[i] * (0.5 * dt)) / (1 + 0.5 * dt * c[i]);
    }
  }
  s.t += dt;
}

void step_verlet(System& s, double dt, int threads) { step_verlet(s, dt, threads, {}); }

}  // namespace swarm
