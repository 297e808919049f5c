// The system's totals, checked on masses whose sums are done by hand.

#include "swarm/physics/system.h"

#include <doctest/doctest.h>

using namespace swarm;

TEST_CASE("total mass, centre of mass and its velocity are the mass-weighted sums") {
  System s;
  s.J = 0.5;
  s.particles = {{1.0, {0, 0, 0}, {1, 0, 0}}, {3.0, {4, 0, 0}, {0, 2, 0}}};
  CHECK(total_mass(s) == 4.0);
  // R = (1 * 0 + 3 * 4) / 4 = 3; V = (1 * (1, 0, 0) + 3 * (0, 2, 0)) / 4.
  CHECK((cm_position(s) - Vec3(3, 0, 0)).norm() < 1e-15);
  CHECK((cm_velocity(s) - Vec3(0.25, 1.5, 0)).norm() < 1e-15);
}

TEST_CASE("stiffness is J M, the squared frequency with the sign of J") {
  System s;
  s.particles = {{2.0, {1, 0, 0}, {}}, {0.5, {-1, 0, 0}, {}}};
  s.J = 1.6;
  CHECK(stiffness(s) == doctest::Approx(4.0));
  s.J = -1.6;
  CHECK(stiffness(s) == doctest::Approx(-4.0));
  s.J = 0;
  CHECK(stiffness(s) == 0.0);
}
