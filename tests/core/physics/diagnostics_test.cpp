#include "swarm/physics/diagnostics.h"

#include <cmath>

#include <doctest/doctest.h>

#include "swarm/methods/integrators.h"
#include "test_systems.h"

using namespace swarm;
using doctest::Approx;

TEST_CASE("two bodies by hand: KE, PE = J m1 m2 d^2 / 2, momentum, angular momentum") {
  System s;
  s.J = 2.0;
  s.particles = {{1.0, {0, 0, 0}, {1, 0, 0}}, {3.0, {2, 0, 0}, {0, 1, 0}}};
  CHECK(kinetic_energy(s) == Approx(0.5 * 1 + 0.5 * 3));
  CHECK(potential_energy_pairwise(s) == Approx(0.5 * 2.0 * 1 * 3 * 4));
  CHECK(potential_energy_cm(s) == Approx(12.0));
  CHECK(total_energy(s) == Approx(14.0));
  CHECK((total_momentum(s) - Vec3(1, 3, 0)).norm() < 1e-15);
  // CM at x = 1.5 moving at (0.25, 0.75); relative: (-1.5,0,0)x(0.75,-0.75,0) and
  // (0.5,0,0)x(-0.25,0.25,0).
  const Vec3 L = angular_momentum_cm(s);
  CHECK(L.z() == Approx(1.0 * 1.5 * 0.75 + 3.0 * 0.5 * 0.25));
}

TEST_CASE("pairwise (eq. 8) and CM (eq. 13) potential energies agree for any J") {
  for (double J : {1.3, -0.7, 0.0}) {
    const System s = testing::random_swarm(300, J, 11, 2.0);
    CHECK(potential_energy_cm(s) ==
          Approx(potential_energy_pairwise(s)).epsilon(1e-12).scale(1e-300));
  }
}

TEST_CASE("a sample's reading: the energies, the CM and the size, to the bit as taken apart") {
  // By hand: masses 1 and 3 at x = 0 and 2, the CM at 1.5; sum m d^2 = 2.25 + 0.75 = 3, M = 4.
  System two;
  two.J = 2.0;
  two.particles = {{1.0, {0, 0, 0}, {1, 0, 0}}, {3.0, {2, 0, 0}, {0, 1, 0}}};
  const SwarmReading by_hand = swarm_reading(two);
  CHECK(by_hand.cm.x() == Approx(1.5));
  CHECK(by_hand.size == Approx(std::sqrt(0.75)));
  CHECK(by_hand.energy.potential == Approx(0.5 * (2.0 * 4) * 3));
  // A run's samples must not change with how they are read: the same sums in the same order as
  // the functions that read each part alone (kinetic_energy, cm_position) give the same bits,
  // and the potential agrees with the pairwise sum of eq. 8.
  for (double J : {1.3, -0.7}) {
    const System s = testing::random_swarm(3000, J, 17, 2.0);
    const SwarmReading r = swarm_reading(s);
    CHECK(r.energy.kinetic == kinetic_energy(s));
    CHECK(r.cm == cm_position(s));
    const Vec3 R = cm_position(s);
    double sum = 0;
    for (const Particle& p : s.particles) sum += p.m * (p.r - R).squaredNorm();
    CHECK(r.size == std::sqrt(sum / total_mass(s)));
    CHECK(r.energy.potential == Approx(potential_energy_pairwise(s)).epsilon(1e-11));
  }
}

TEST_CASE("the kinetic energy in the CM frame: by hand, and as sum 1/2 m |v - V_cm|^2") {
  // By hand: masses 1 and 3 moving at (1,0,0) and (0,1,0); V_cm = (1/4, 3/4, 0); relative
  // speeds^2 (3/4)^2 + (3/4)^2 = 9/8 and (1/4)^2 + (1/4)^2 = 1/8: KE_cm = 9/16 + 3/16 = 3/4.
  System two;
  two.particles = {{1.0, {0, 0, 0}, {1, 0, 0}}, {3.0, {2, 0, 0}, {0, 1, 0}}};
  CHECK(swarm_reading(two).kinetic_cm == Approx(0.75));
  // A swarm given a drift: KE_cm is the drift-free KE, whatever the drift.
  System s = testing::random_swarm(3000, 1.3, 17, 2.0);
  const Vec3 V = total_momentum(s) / total_mass(s);
  double direct = 0;
  for (const Particle& p : s.particles) direct += 0.5 * p.m * (p.v - V).squaredNorm();
  for (Particle& p : s.particles) p.v += Vec3(5, -3, 2);
  CHECK(swarm_reading(s).kinetic_cm == Approx(direct).epsilon(1e-11));
  CHECK(kinetic_energy(s) > 2 * direct);  // the drift's share is left out
}

TEST_CASE("the pairwise integrators conserve momentum exactly (Newton's third law)") {
  System s = testing::random_swarm(40, 1.0, 5);
  const Vec3 P0 = total_momentum(s);
  for (Method m : {Method::euler, Method::euler_cromer, Method::verlet, Method::rk4}) {
    System n = s;
    for (int i = 0; i < 50; ++i) step(m, n, 1e-2);
    CHECK((total_momentum(n) - P0).norm() < 1e-11);
  }
}
