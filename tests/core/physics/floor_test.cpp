#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "swarm/engine/engine.h"
#include "swarm/physics/diagnostics.h"
#include "swarm/physics/floor.h"
#include "swarm/physics/gravity.h"
#include "test_systems.h"

using namespace swarm;

namespace {

/// An attractive swarm of 60 particles (masses 4-5, J M = 25: a size of about 0.2) released
/// with its CM 2 above the floor z = 0, moving sideways, under g = (0, 0, -9.8).
System swarm_above_floor() {
  System s = testing::random_swarm(60, 1.0, 7, 0.3, 1.0);
  s.J = 25.0 / total_mass(s);
  const Vec3 lift(0, 0, 2.0), sideways(0.7, -0.3, 0);
  for (auto& p : s.particles) p.r += lift, p.v += sideways;
  return s;
}

double energy_with_gravity(const System& s, const Vec3& g) {
  return total_energy(s) + gravity_potential_energy(s, g);
}

/// An engine for s under gravity g above the floor z = 0 of restitution e.
std::unique_ptr<Engine> on_floor(const System& s, CollisionMode mode, const Vec3& g, double e) {
  EngineConfig config;
  config.collisions = mode;
  config.forces.gravity = g;
  config.floor = Floor{0, e};
  return make_engine(s, config);
}

}  // namespace

TEST_CASE("a floor bounce: v_z -> -e v_z, the lost kinetic energy booked as negative work") {
  Particle p{2.0, {0, 0, 0.1}, {1, 0, -3}};
  WallTally tally;
  bounce_on_floor(p, Floor{0, 0.5}, tally);
  CHECK(p.v.z() == doctest::Approx(1.5));
  CHECK(p.v.x() == 1);
  CHECK(tally.floor_hits == 1);
  CHECK(tally.hits == 0);  // the container's thermometry does not count the floor
  CHECK(tally.books.wall_work == doctest::Approx(-0.5 * 2.0 * (1 - 0.25) * 9));
  CHECK(tally.wall_momentum.z() == doctest::Approx(-2.0 * 4.5));
}

TEST_CASE("an elastic floor under gravity: energy kept to rounding over thousands of bounces") {
  const Vec3 g(0, 0, -9.8);
  for (CollisionMode mode : {CollisionMode::paper, CollisionMode::exact}) {
    const std::string mode_name(name_of(mode));
    CAPTURE(mode_name);
    const System s = swarm_above_floor();
    auto engine = on_floor(s, mode, g, 1);
    const double E0 = energy_with_gravity(s, g);
    const Vec3 V0 = cm_velocity(s);
    std::int64_t bounces = 0;
    double worst = 0;
    for (int i = 0; i < 15000; ++i) {
      bounces += engine->step(2e-3).floor_hits;
      if (i % 100 == 0)
        worst = std::max(worst, std::abs(energy_with_gravity(engine->system(), g) - E0));
    }
    CHECK(bounces >= 1000);
    CHECK(worst / std::abs(E0) < 1e-11);
    // Gravity and the floor push only along z: the CM's horizontal velocity is untouched.
    const Vec3 V = cm_velocity(engine->system());
    CHECK(std::abs(V.x() - V0.x()) < 1e-11);  // rounding of the CM sums, 15,000 steps
    CHECK(std::abs(V.y() - V0.y()) < 1e-11);
    // And everyone stays (up to one step's excursion) above the floor.
    for (const auto& p : engine->system().particles) CHECK(p.r.z() > -0.1);
  }
}

TEST_CASE("an inelastic floor: the energy falls by exactly the work the books record") {
  const Vec3 g(0, 0, -9.8);
  const System s = swarm_above_floor();
  EngineConfig config;
  config.forces.gravity = g;
  config.floor = Floor{0, 0.8};
  auto engine = make_engine(s, config);
  EnergyBooks books;
  for (int i = 0; i < 3000; ++i) books.add(engine->step(2e-3).books);
  const double E0 = energy_with_gravity(s, g), E = energy_with_gravity(engine->system(), g);
  CHECK(books.wall_work < -0.1 * std::abs(E0));
  CHECK(E - E0 == doctest::Approx(books.net()).epsilon(1e-10));
}

TEST_CASE("an inelastic floor: the swarm comes to rest on it and never ends a step below it") {
  // Without the resting contact a particle bouncing too slowly to clear the floor within a
  // step sank by g dt (1 - e) / (2 (1 + e)) a step: the whole swarm below the floor in time.
  const Vec3 g(0, 0, -9.8);
  const double dt = 2e-3;
  for (CollisionMode mode : {CollisionMode::paper, CollisionMode::exact}) {
    const std::string mode_name(name_of(mode));
    CAPTURE(mode_name);
    const System s = swarm_above_floor();
    auto engine = on_floor(s, mode, g, 0.5);
    EnergyBooks books;
    double lowest = 1;
    for (int i = 0; i < 4000; ++i) {
      books.add(engine->step(dt).books);
      for (const auto& p : engine->system().particles) lowest = std::min(lowest, p.r.z());
    }
    CHECK(lowest >= 0);
    // At rest: every bounce lost vertical energy, and the springs resist no squeeze along z,
    // so the swarm ends as a disc on the floor (the drop reached |v_z| = sqrt(2 g 2) = 6.3),
    // still swinging about its CM along the floor.
    const System& end = engine->system();
    double highest = 0, fastest_z = 0;
    for (const auto& p : end.particles) {
      highest = std::max(highest, p.r.z());
      fastest_z = std::max(fastest_z, std::abs(p.v.z()));
    }
    CHECK(highest < 1e-3);
    CHECK(fastest_z < 0.05);
    CHECK(kinetic_energy(end) > 0.1 * kinetic_energy(s));
    const double E0 = energy_with_gravity(s, g), E = energy_with_gravity(end, g);
    CHECK(E - E0 == doctest::Approx(books.net()).epsilon(1e-10));
  }
}
