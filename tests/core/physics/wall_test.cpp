// The elastic reflection at the spherical wall against the geometry of a mirror: the radial
// velocity turns round, the tangential one stays, and the wall takes the momentum.

#include "swarm/physics/wall.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace swarm;

TEST_CASE("a reflection reverses the radial velocity and keeps the tangential one") {
  // At r = (0, 3, 4) / 5 * R the outward normal is (0, 0.6, 0.8).
  Particle p{2.0, {0, 1.8, 2.4}, {1.0, 2.0, 1.0}};
  const Vec3 n(0, 0.6, 0.8);
  const double v_r = p.v.dot(n);  // 2.0
  const Vec3 tangential = p.v - v_r * n;
  WallTally tally;
  reflect_at_wall(p, tally);
  CHECK(p.v.dot(n) == doctest::Approx(-v_r));
  CHECK((p.v - p.v.dot(n) * n - tangential).norm() < 1e-15);
  CHECK(p.v.norm() == doctest::Approx(std::sqrt(6.0)));  // elastic
  CHECK(tally.hits == 1);
  CHECK(tally.radial_impulse == doctest::Approx(2 * 2.0 * v_r));
  CHECK(tally.hit_kinetic_energy == doctest::Approx(0.5 * 2.0 * 6.0));
  // The particle's momentum changed by -2 m v_r n; the wall took up the opposite.
  CHECK((tally.wall_momentum - 2 * 2.0 * v_r * n).norm() < 1e-14);
}

TEST_CASE("tallies add hit by hit") {
  WallTally a, b;
  Particle p{1.0, {1, 0, 0}, {1, 0, 0}}, q{1.0, {0, 1, 0}, {0, 3, 0}};
  reflect_at_wall(p, a);
  reflect_at_wall(q, b);
  a.add(b);
  CHECK(a.hits == 2);
  CHECK(a.radial_impulse == doctest::Approx(2 * 1 + 2 * 3));
  CHECK((a.wall_momentum - Vec3(2, 6, 0)).norm() < 1e-15);
}

TEST_CASE("sphere area and volume") {
  CHECK(sphere_area(2.0) == doctest::Approx(16 * M_PI));
  CHECK(sphere_volume(3.0) == doctest::Approx(36 * M_PI));
}
