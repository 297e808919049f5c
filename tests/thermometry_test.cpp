#include "swarm/thermometry.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace swarm;
using doctest::Approx;

TEST_CASE("wall pressure and temperature follow the paper's definitions, by hand") {
  // One particle of mass 2 hits the wall head-on at speed 3 with tangential speed 4.
  Particle p{2.0, {0, 0, 1}, {4, 0, 3}};
  WallTally t;
  reflect_at_wall(p, t);
  CHECK(t.hits == 1);
  CHECK(t.radial_impulse == Approx(2 * 2.0 * 3));
  CHECK(t.hit_kinetic_energy == Approx(0.5 * 2.0 * 25));
  CHECK((p.v - Vec3(4, 0, -3)).norm() < 1e-15);
  CHECK((t.wall_momentum - Vec3(0, 0, 12)).norm() < 1e-15);

  WallMeter meter;
  const double R = 2.0, dt = 0.01;
  meter.add(t, dt, R);
  meter.add(WallTally{}, dt, R);
  const WallReading w = meter.reading();
  CHECK(w.P == Approx(12.0 / (4 * M_PI * R * R * 2 * dt)));
  CHECK(w.T == Approx(0.5 * 25.0));  // half the hitters' mean kinetic energy (k_B = 1)
  meter.reset();
  CHECK(meter.reading().P == 0);
  CHECK(meter.reading().T == 0);
}
