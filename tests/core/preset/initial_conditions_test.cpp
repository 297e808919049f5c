#include "swarm/preset/initial_conditions.h"

#include <doctest/doctest.h>

#include <cmath>

#include "swarm/physics/diagnostics.h"

using namespace swarm;
using doctest::Approx;

TEST_CASE("a seed gives the same swarm; another seed another") {
  SwarmSpec spec;
  spec.count = 500;
  spec.mass_min = 4;
  spec.mass_max = 5;
  spec.seed = 42;
  const System a = generate_swarm(spec), b = generate_swarm(spec);
  spec.seed = 43;
  const System c = generate_swarm(spec);
  for (std::size_t i = 0; i < a.particles.size(); ++i) {
    CHECK(a.particles[i].r == b.particles[i].r);
    CHECK(a.particles[i].v == b.particles[i].v);
  }
  CHECK(a.particles[0].r != c.particles[0].r);
}

TEST_CASE("uniform masses, positions uniform in the ball, velocities in the ball") {
  SwarmSpec spec;
  spec.count = 20000;
  spec.mass_min = 4;
  spec.mass_max = 5;
  spec.position_radius = 2;
  spec.speed = 0.5;
  const System s = generate_swarm(spec);
  double mean_m = 0, mean_r3 = 0;
  for (const auto& p : s.particles) {
    CHECK(p.m >= 4);
    CHECK(p.m <= 5);
    CHECK(p.r.norm() <= 2);
    CHECK(p.v.norm() <= 0.5);
    mean_m += p.m / spec.count;
    mean_r3 += std::pow(p.r.norm() / 2, 3) / spec.count;  // uniform in volume: U(0, 1)
  }
  CHECK(mean_m == Approx(4.5).epsilon(0.01));
  CHECK(mean_r3 == Approx(0.5).epsilon(0.02));
}

TEST_CASE("Maxwellian velocities at temperature T give <m v^2 / 2> = 3 T / 2") {
  SwarmSpec spec;
  spec.count = 20000;
  spec.mass_min = 1;
  spec.mass_max = 9;
  spec.velocities = SwarmSpec::Velocities::maxwell;
  spec.temperature = 0.7;
  spec.cm_at_rest = true;
  const System s = generate_swarm(spec);
  CHECK(kinetic_energy(s) / spec.count == Approx(1.5 * 0.7).epsilon(0.02));
  CHECK(cm_velocity(s).norm() < 1e-12);
}
