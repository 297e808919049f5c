#include "swarm/methods/external_forces.h"
#include "swarm/methods/integrators.h"

namespace swarm {

void step_rk4(System& s, double dt, int threads, const ExternalForces& f) {
  const std::size_t n = s.particles.size();
  const System start = s;
  std::vector<Vec3> a1, a2, a3, a4, v2(n), v3(n), v4(n);

  // Stage k evaluates the derivative (v, a) at start + c_k dt * previous derivative.
  auto stage = [&](const std::vector<Vec3>& dr, const std::vector<Vec3>& dv, double h,
                   std::vector<Vec3>& v_out, std::vector<Vec3>& a_out) {
    System mid = start;
    for (std::size_t i = 0; i < n; ++i) {
      mid.particles[i].r += dr[i] * h;
      mid.particles[i].v += dv[i] * h;
      v_out[i] = mid.particles[i].v;
    }
    accelerations(mid, f, a_out, threads);
  };

  std::vector<Vec3> v1(n);
  for (std::size_t i = 0; i < n; ++i) v1[i] = start.particles[i].v;
  accelerations(start, f, a1, threads);
  stage(v1, a1, 0.5 * dt, v2, a2);
  stage(v2, a2, 0.5 * dt, v3, a3);
  stage(v3, a3, dt, v4, a4);
  for (std::size_t i = 0; i < n; ++i) {
    s.particles[i].r += (dt / 6) * (v1[i] + 2 * v2[i] + 2 * v3[i] + v4[i]);
    s.particles[i].v += (dt / 6) * (a1[i] + 2 * a2[i] + 2 * a3[i] + a4[i]);
  }
  s.t += dt;
}

void step_rk4(System& s, double dt, int threads) { step_rk4(s, dt, threads, {}); }

}  // namespace swarm
