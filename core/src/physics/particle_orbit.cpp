#include "swarm/physics/particle_orbit.h"

#include <cmath>

#include "swarm/physics/analytic.h"
#include "swarm/physics/regime.h"

namespace swarm {

ParticleOrbit particle_orbit(const Particle& p, const Vec3& cm_position, const Vec3& cm_velocity,
                             double k) {
  const Vec3 x = p.r - cm_position, u = p.v - cm_velocity;
  ParticleOrbit o;
  o.m = p.m;
  o.distance = x.norm();
  o.speed = p.v.norm();
  o.speed_cm = u.norm();
  o.kinetic_cm = 0.5 * p.m * u.squaredNorm();
  o.spring = 0.5 * k * p.m * x.squaredNorm();
  o.energy = o.kinetic_cm + o.spring;
  if (regime_of(k) == Regime::attractive) {
    // x(t) = x cos(omega t) + (u / omega) sin(omega t) from now on (eq. 7).
    const OrbitEllipse e = ellipse_of(x, u / omega_of(k));
    o.period = period_of(k);
    o.semi_major = e.semi_major.norm();
    o.semi_minor = e.semi_minor.norm();
  }
  return o;
}

}  // namespace swarm
