// The fast engine against a thermal and a moving wall: the wall's rules (fast_engine_wall.h)
// are the physics layer's, and whole runs hit in the same steps as the reference engine, end in
// the same state and keep books that balance.

#include "engine/fast_engine_wall.h"

#include <doctest/doctest.h>

#include <cmath>

#include "core/engine/engines_side_by_side.h"
#include "swarm/engine/engine.h"
#include "swarm/engine/fast_engine.h"
#include "swarm/measure/speed_distribution.h"
#include "swarm/physics/diagnostics.h"
#include "swarm/physics/gravity.h"
#include "swarm/physics/thermal_wall.h"
#include "swarm/physics/wall_motion.h"
#include "test_systems.h"

using namespace swarm;
using testing::crowded_swarm;
using testing::max_state_difference;
using testing::require_same_run;
using testing::SideBySideRun;

namespace {

/// The energy the gas exchanged with the wall is not lost in rounding: at least this share of
/// its kinetic energy.
void check_exchange(const System& s, const EnergyBooks& books, double share) {
  CHECK(std::abs(books.net()) > share * kinetic_energy(s));
}

EngineConfig wall_config() {
  EngineConfig config;
  config.container_radius = 1.0;
  return config;
}

}  // namespace

TEST_CASE("SphereWall: a moving wall's particle leaves when it outruns the wall") {
  fast::SphereWall wall;
  wall.moving = true;
  wall.u = 0.3;  // moving out
  const Vec3 r{0.9, 0, 0};
  CHECK_FALSE(wall.leaving(r, {0.2, 0, 0}));  // outward, but slower than the wall
  CHECK(wall.leaving(r, {0.4, 0, 0}));
  wall.u = -0.3;  // moving in: a particle drifting in slower than it still meets it
  CHECK(wall.leaving(r, {-0.2, 0, 0}));
  wall.moving = false;
  wall.u = 0;
  CHECK_FALSE(wall.leaving(r, {-0.2, 0, 0}));
}

TEST_CASE("SphereWall: its hits are the reference engine's, velocity, tally and books") {
  const Particle p{2.0, {0.6, -0.5, 0.3}, {0.7, -0.1, 0.4}};
  SUBCASE("moving") {
    fast::SphereWall wall;
    wall.moving = true;
    wall.u = -0.25;
    WallTally fast_tally, tally;
    const Vec3 dv = wall.hit(p.m, p.r, p.v, 7, fast_tally);
    Particle q = p;
    reflect_off_moving_wall(q, -0.25, tally);
    CHECK(p.v + dv == q.v);
    CHECK(fast_tally.radial_impulse == tally.radial_impulse);
    CHECK(fast_tally.books.wall_work == tally.books.wall_work);
    CHECK(tally.books.wall_work > 0);  // a wall moving in does work on the gas
  }
  SUBCASE("thermal: the same draw for the same step, particle and stream") {
    fast::SphereWall wall;
    wall.temperature = 1.7;
    wall.step = 123;
    wall.stream = 99;
    WallTally fast_tally, tally;
    const Vec3 dv = wall.hit(p.m, p.r, p.v, 7, fast_tally);
    Particle q = p;
    reemit_from_thermal_wall(q, 1.7, {123, 7, 99}, tally);
    CHECK((p.v + dv - q.v).norm() < 1e-15);
    CHECK(fast_tally.books.wall_heat == tally.books.wall_heat);
    CHECK(fast_tally.radial_impulse == tally.radial_impulse);
    // Another particle in the same step draws another velocity.
    WallTally other;
    CHECK((wall.hit(p.m, p.r, p.v, 8, other) - dv).norm() > 1e-3);
  }
}

TEST_CASE("the fast engine hits a thermal wall exactly when the reference engine does") {
  for (const double sign : {+1.0, -1.0, 0.0}) {
    const System s = crowded_swarm(2000, sign, 41);
    const double T_gas = kinetic_temperature(s);
    for (const double hotter : {3.0, 0.3}) {
      CAPTURE(sign);
      CAPTURE(hotter);
      EngineConfig config = wall_config();
      config.wall_temperature = hotter * T_gas;
      config.wall_stream = 17;
      // J < 0 grows differences like exp(Omega t): 3,000 steps keep them within 1e-9.
      const int steps = sign < 0 ? 3000 : 4000;
      const SideBySideRun run = require_same_run(s, config, 1e-3, steps);
      CHECK(run.hits > steps / 4);
      // The fast engine's checks grow with the hits, not with N a step.
      CHECK(double(run.stats.checks) < 0.25 * 2000.0 * steps);
      // A hot wall heats the gas and a cold one cools it.
      CHECK((hotter > 1 ? run.books.wall_heat : -run.books.wall_heat) > 0);
      check_exchange(s, run.books, 0.01);
    }
  }
}

TEST_CASE("the fast engine hits a moving wall exactly when the reference engine does") {
  // In and out, and out and in, at a tenth of the particles' speeds: the anchors' margins
  // are spent by the wall and renewed many times over.
  const std::vector<std::vector<WallMove>> paths = {{{0.8, 0.1}, {1.1, 0.1}},
                                                    {{1.2, 0.1}, {0.9, 0.1}}};
  for (const double sign : {+1.0, -1.0, 0.0}) {
    const System s = crowded_swarm(2000, sign, 43);
    for (std::size_t k = 0; k < paths.size(); ++k) {
      CAPTURE(sign);
      CAPTURE(k);
      EngineConfig config = wall_config();
      config.wall_moves = paths[k];
      const int steps = sign < 0 ? 3000 : 4000;
      const SideBySideRun run = require_same_run(s, config, 1e-3, steps);
      CHECK(run.hits > steps / 4);
      CHECK(double(run.stats.checks) < 0.25 * 2000.0 * steps);
      // The wall really moved both ways within the run.
      const WallPath path(1.0, paths[k]);
      CHECK(std::abs(path.radius_at(steps * 1e-3) - path.radius_at(2.0)) > 0.05);
    }
  }
}

TEST_CASE("a thermal or a moving wall under gravity, drag and a floor: as the reference engine") {
  // The wall's rules (fast_engine_wall.h) through the forces' flow: a hit's dv, whatever the
  // wall, enters the damped coefficients, and the floor is checked after the wall on the same
  // prediction. The anchors hold by the wall's radius and the floor's level together.
  // J < 0 runs shorter: its runaway presses the swarm against the wall within a few time units.
  const Vec3 g(0.1, 0, -0.6);
  for (const double sign : {+1.0, -1.0, 0.0}) {
    const System s = crowded_swarm(2000, sign, 59);
    const double T_gas = kinetic_temperature(s);
    const int steps = sign < 0 ? 800 : 3000;
    for (const bool thermal : {false, true}) {
      for (const double gamma : {0.0, 0.4}) {
        CAPTURE(sign);
        CAPTURE(thermal);
        CAPTURE(gamma);
        EngineConfig config = wall_config();
        if (thermal) {
          config.wall_temperature = 3 * T_gas;
          config.wall_stream = 23;
        } else {
          config.wall_moves = {{0.8, 0.1}, {1.1, 0.1}};
        }
        config.forces.gravity = g;
        if (gamma > 0) config.forces.drag = Drag{gamma, 0, {}};
        config.floor = Floor{-0.3, 1};
        const SideBySideRun run = require_same_run(s, config, 1e-3, steps);
        CHECK(run.hits > steps / 4);
        CHECK(run.floor_hits > steps / 4);  // the floor was in play
        CHECK((thermal ? run.books.wall_heat : run.books.wall_work) != 0);
      }
    }
  }
}

TEST_CASE("a moving wall in the fast engine: a jump of the wall stops it, as in the reference") {
  // The expansion protocol moves the wall discontinuously (set_container_radius); a wall
  // that was moving stops there. dt changes on the way too.
  for (const double sign : {+1.0, -1.0}) {
    CAPTURE(sign);
    const System s = crowded_swarm(2000, sign, 47);
    EngineConfig config = wall_config();
    config.wall_moves = {{0.7, 0.2}};
    const SideBySideRun run = require_same_run(s, config, 1e-3, 3000, [](int i, Engine& engine) {
      if (i == 1000) engine.set_container_radius(0.95);
      if (i == 2000) engine.set_container_radius(0.9);
    });
    CHECK(run.hits > 3000 / 4);
  }
}

TEST_CASE("a fast engine with a moving or a thermal wall clones into one that steps on alike") {
  const System s = crowded_swarm(500, +1.0, 53);
  for (const bool thermal : {false, true}) {
    CAPTURE(thermal);
    EngineConfig config = wall_config();
    if (thermal)
      config.wall_temperature = 2.0;
    else
      config.wall_moves = {{0.8, 0.2}};
    auto engine = make_fast_engine(s, config);
    for (int i = 0; i < 500; ++i) engine->step(1e-3);
    auto copy = engine->clone();
    for (int i = 0; i < 1000; ++i) REQUIRE(engine->step(1e-3).hits == copy->step(1e-3).hits);
    CHECK(engine->container_radius() == copy->container_radius());
    CHECK(max_state_difference(engine->system(), copy->system()) == 0);
  }
}

TEST_CASE("make_engine runs moving and thermal walls on the fast engine, hard spheres not") {
  EngineConfig config = wall_config();
  config.wall_moves = {{0.8, 0.1}};
  CHECK(fast_engine_applies(config));
  config.forces.gravity = {0, 0, -1};
  config.forces.drag = Drag{0.5, 0, {}};
  config.floor = Floor{-0.5, 1};
  CHECK(fast_engine_applies(config));  // with forces and an elastic floor too
  config.floor = Floor{-0.5, 0.5};
  CHECK_FALSE(fast_engine_applies(config));  // an inelastic floor: the reference engine
  config.floor.reset();
  config.wall_moves.clear();
  config.wall_temperature = 1.0;
  CHECK(fast_engine_applies(config));
  config.sphere_radius = 0.01;
  CHECK_FALSE(fast_engine_applies(config));
}
