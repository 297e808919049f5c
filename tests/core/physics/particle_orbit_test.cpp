#include "swarm/physics/particle_orbit.h"

#include <doctest/doctest.h>

#include <cmath>

#include "swarm/physics/analytic.h"
#include "swarm/physics/diagnostics.h"
#include "test_systems.h"

using namespace swarm;
using doctest::Approx;

TEST_CASE("the particles' CM-frame energies and the CM's kinetic energy sum to the total") {
  // Checked against the pairwise potential of eq. 8 (no CM shortcut) and the lab kinetic
  // energy, for both signs of J and a swarm whose CM moves.
  for (double J : {0.7, -0.3}) {
    System s = testing::random_swarm(40, J, 7);
    for (Particle& p : s.particles) p.v += Vec3(0.4, -0.2, 0.1);
    const Vec3 R = cm_position(s), V = cm_velocity(s);
    const double M = total_mass(s), k = J * M;
    double sum = 0.5 * M * V.squaredNorm(), springs = 0;
    for (const Particle& p : s.particles) {
      const ParticleOrbit o = particle_orbit(p, R, V, k);
      CHECK(o.energy == Approx(o.kinetic_cm + o.spring));
      sum += o.energy;
      springs += o.spring;
    }
    CAPTURE(J);
    CHECK(springs == Approx(potential_energy_pairwise(s)).epsilon(1e-12));
    CHECK(sum == Approx(kinetic_energy(s) + potential_energy_pairwise(s)).epsilon(1e-12));
  }
}

TEST_CASE("a particle's card: distance, speeds, energy by hand; period and axes of its ellipse") {
  // CM at (1, 0, 0) moving at (0, 1, 0); the particle 2 to the right of it, moving (0, 3, 0)
  // in the lab: in the CM frame it is at (2, 0, 0) with velocity (0, 2, 0).
  const Particle p{0.5, {3, 0, 0}, {0, 3, 0}};
  const double k = 4;  // omega = 2: the orbit x = 2 cos(2t), y = sin(2t)
  const ParticleOrbit o = particle_orbit(p, Vec3(1, 0, 0), Vec3(0, 1, 0), k);
  CHECK(o.m == 0.5);
  CHECK(o.distance == Approx(2));
  CHECK(o.speed == Approx(3));
  CHECK(o.speed_cm == Approx(2));
  CHECK(o.kinetic_cm == Approx(0.5 * 0.5 * 4));
  CHECK(o.spring == Approx(0.5 * 4 * 0.5 * 4));
  REQUIRE(o.period.has_value());
  CHECK(*o.period == Approx(M_PI));
  CHECK(*o.semi_major == Approx(2));
  CHECK(*o.semi_minor == Approx(1));

  const ParticleOrbit runaway = particle_orbit(p, Vec3(1, 0, 0), Vec3(0, 1, 0), -4);
  CHECK(!runaway.period.has_value());
  CHECK(!runaway.semi_major.has_value());
  CHECK(runaway.spring == Approx(-0.5 * 4 * 0.5 * 4));
}

TEST_CASE("a particle's orbit energy holds along the exact orbit (no wall)") {
  const System s = testing::four_masses(1.3);
  const AnalyticSolution exact(s);
  const double k = stiffness(s);
  for (std::size_t i = 0; i < s.particles.size(); ++i) {
    const double e0 = particle_orbit(s.particles[i], cm_position(s), cm_velocity(s), k).energy;
    const double t = 2.7;
    const ParticleOrbit later =
        particle_orbit(exact.particle_at(i, t), exact.cm_position_at(t), exact.cm_velocity(), k);
    CHECK(later.energy == Approx(e0).epsilon(1e-12));
  }
}
