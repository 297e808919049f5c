#include "swarm/methods/external_forces.h"

#include <cmath>

#include "math/portable_math.h"
#include "swarm/methods/integrators.h"
#include "swarm/physics/diagnostics.h"
#include "swarm/physics/flow.h"
#include "swarm/physics/gravity.h"

namespace swarm {
namespace {

/// (t - (1 - exp(-gamma t)) / gamma) / gamma, the CM's displacement per unit g under drag,
/// t^2 / 2 when gamma t -> 0. The series below gamma t = 0.1 avoids the cancellation of the
/// closed form there (14 terms: the next is below 1e-16 of the sum).
double free_fall_factor(double gamma, double t, double one_minus_decay_over_gamma) {
  const double x = gamma * t;
  if (x < 0.1) {
    double term = 0.5, sum = 0;  // (-x)^n / (n + 2)!
    for (int n = 0; n < 14; ++n) {
      sum += term;
      term *= -x / double(n + 3);
    }
    return t * t * sum;
  }
  return (t - one_minus_decay_over_gamma) / gamma;
}

}  // namespace

ForcedFlow ForcedFlow::over(double k, double gamma, double t) {
  ForcedFlow out;
  if (gamma == 0) {
    const Flow f = Flow::over(k, t);
    out.xc = f.c, out.xs = f.s, out.vc = f.dc(), out.vs = f.c;
    out.cm_v = t, out.cm_g = 0.5 * t * t, out.cm_vv = 1, out.cm_vg = t;
    return out;
  }
  // x'' = -k x - gamma x': x = exp(-h t) (C x0 + S (v0 + h x0)) with h = gamma / 2 and C, S the
  // undamped flow's c, s for the stiffness k - h^2 (cos / sin, critical 1 / t, cosh / sinh).
  const double h = 0.5 * gamma;
  const Flow f = Flow::over(k - h * h, t);
  const double E = portable::exp(-h * t);
  out.xc = E * (f.c + h * f.s);
  out.xs = E * f.s;
  out.vc = -k * E * f.s;
  out.vs = E * (f.c - h * f.s);
  const double phi = -portable::expm1(-gamma * t) / gamma;  // (1 - exp(-gamma t)) / gamma
  out.cm_v = phi;
  out.cm_vg = phi;
  out.cm_vv = portable::exp(-gamma * t);
  out.cm_g = free_fall_factor(gamma, t, phi);
  return out;
}

void step_analytic_forced(System& s, double dt, const ExternalForces& f) {
  // As step_analytic: the CM from the particles every step, then everyone on the exact map.
  const Vec3 R = cm_position(s);
  const Vec3 V = cm_velocity(s);
  const ForcedFlow m = ForcedFlow::over(stiffness(s), f.drag ? f.drag->gamma : 0.0, dt);
  const Vec3 R_next = R + m.cm_v * V + m.cm_g * f.gravity;
  const Vec3 V_next = m.cm_vv * V + m.cm_vg * f.gravity;
  for (auto& p : s.particles) {
    const Vec3 x = p.r - R;
    const Vec3 u = p.v - V;
    p.r = R_next + m.xc * x + m.xs * u;
    p.v = V_next + m.vc * x + m.vs * u;
  }
  s.t += dt;
}

void accelerations(const System& s, const ExternalForces& f, std::vector<Vec3>& a, int threads) {
  pairwise_accelerations(s, a, threads);
  if (!f.any()) return;  // not even + 0: the plain methods keep their bits
  const std::vector<double> c =
      f.drag ? drag_rates(*f.drag, s) : std::vector<double>(s.particles.size(), 0.0);
  for (std::size_t i = 0; i < s.particles.size(); ++i)
    a[i] += f.gravity - c[i] * s.particles[i].v;
}

double step_with_forces(Method m, System& s, double dt, int threads, const ExternalForces& f) {
  if (m == Method::analytic) {
    if (!f.drag) {
      step_analytic_forced(s, dt, f);
      return 0;
    }
    // The map is exact, so the energy it loses is exactly what the drag took.
    const double before = total_energy(s) + gravity_potential_energy(s, f.gravity);
    step_analytic_forced(s, dt, f);
    return before - (total_energy(s) + gravity_potential_energy(s, f.gravity));
  }
  const std::vector<double> c = f.drag ? drag_rates(*f.drag, s) : std::vector<double>{};
  const double power_before = f.drag ? drag_power(c, s) : 0.0;
  switch (m) {
    case Method::euler:
      step_euler(s, dt, threads, f);
      break;
    case Method::euler_cromer:
      step_euler_cromer(s, dt, threads, f);
      break;
    case Method::verlet:
      step_verlet(s, dt, threads, f);
      break;
    case Method::rk4:
      step_rk4(s, dt, threads, f);
      break;
    case Method::analytic:
      break;
  }
  return f.drag ? 0.5 * dt * (power_before + drag_power(c, s)) : 0.0;
}

}  // namespace swarm
