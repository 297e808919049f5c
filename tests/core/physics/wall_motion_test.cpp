// A moving wall against the physics: slow compression of a free (J = 0) gas is adiabatic,
// the energy changes by exactly the work the wall did, and a finite-speed cycle heats the gas.

#include <doctest/doctest.h>

#include <cmath>

#include "swarm/engine/engine.h"
#include "swarm/measure/speed_distribution.h"
#include "swarm/physics/diagnostics.h"
#include "swarm/physics/wall_motion.h"
#include "swarm/preset/initial_conditions.h"
#include "test_systems.h"

using namespace swarm;

namespace {

/// n particles of mass 1 at temperature 1 (Maxwellian) in the unit ball, J = 0.
System free_gas(long n, std::uint64_t seed, double J = 0) {
  SwarmSpec spec;
  spec.count = n;
  spec.position_radius = 0.95;
  spec.velocities = SwarmSpec::Velocities::maxwell;
  spec.temperature = 1;
  spec.cm_at_rest = true;
  spec.seed = seed;
  System s = generate_swarm(spec);
  s.J = J;
  return s;
}

struct Cycle {
  double E0 = 0, E1 = 0, work = 0, T0 = 0, T1 = 0;
};

Cycle run_moves(System s, std::vector<WallMove> moves, double dt, double extra_time = 0) {
  EngineConfig config;
  config.container_radius = 1.0;
  config.wall_moves = moves;
  auto engine = make_engine(s, config);
  Cycle c;
  c.E0 = total_energy(engine->system());
  c.T0 = kinetic_temperature(engine->system());
  const double T_end = WallPath(1.0, moves).end_time() + extra_time;
  const long steps = std::lround(T_end / dt);
  for (long i = 0; i < steps; ++i) c.work += engine->step(dt).books.wall_work;
  c.E1 = total_energy(engine->system());
  c.T1 = kinetic_temperature(engine->system());
  return c;
}

}  // namespace

TEST_CASE("WallPath: the radius moves at each leg's speed towards its target, then stays") {
  const WallPath path(2.0, {{1.0, 0.5}, {3.0, 1.0}});
  CHECK(path.radius_at(0) == 2.0);
  CHECK(path.radius_at(1.0) == doctest::Approx(1.5));
  CHECK(path.radius_at(2.0) == doctest::Approx(1.0));
  CHECK(path.radius_at(3.0) == doctest::Approx(2.0));
  CHECK(path.end_time() == doctest::Approx(4.0));
  CHECK(path.radius_at(10.0) == 3.0);
}

TEST_CASE("WallPath: the lowest radius over an interval is at its ends or a turn inside it") {
  const WallPath path(2.0, {{1.0, 0.5}, {3.0, 1.0}});  // in until t = 2, out until t = 4
  CHECK(path.lowest_between(0.0, 1.0) == path.radius_at(1.0));
  CHECK(path.lowest_between(1.0, 3.0) == doctest::Approx(1.0));
  CHECK(path.lowest_between(2.5, 3.5) == path.radius_at(2.5));
  CHECK(path.lowest_between(-1.0, 0.0) == 2.0);
  CHECK(path.lowest_between(5.0, 9.0) == 3.0);
}

TEST_CASE("reflect_off_moving_wall reverses the velocity relative to the wall, and books the work") {
  Particle p{2.0, {1, 0, 0}, {0.5, 0.3, 0}};
  WallTally tally;
  reflect_off_moving_wall(p, -0.2, tally);  // the wall moves inward at 0.2
  // v_r - u = 0.7 becomes -0.7: v_r = u - 0.7 = -0.9; the tangential part is untouched.
  CHECK(p.v.x() == doctest::Approx(-0.9));
  CHECK(p.v.y() == doctest::Approx(0.3));
  CHECK(tally.radial_impulse == doctest::Approx(2 * 2.0 * 0.7));
  CHECK(tally.books.wall_work == doctest::Approx(0.5 * 2.0 * (0.81 - 0.25)));
}

TEST_CASE("Moving wall: slow compression of a J = 0 gas keeps T V^(2/3) constant") {
  // Each free particle's radial action is an adiabatic invariant; by scaling, E R^2 stays
  // constant for every orbit, so T R^2 = T V^(2/3) (4 pi / 3)^(-2/3) is constant.
  // Thermal speed ~1.7 against a wall at 0.01.
  const Cycle c = run_moves(free_gas(400, 3), {{0.7, 0.01}}, 2e-3);
  const double ratio = (c.T1 * 0.7 * 0.7) / (c.T0 * 1.0 * 1.0);
  CAPTURE(c.T0);
  CAPTURE(c.T1);
  CHECK(ratio == doctest::Approx(1.0).epsilon(0.03));
  CHECK(c.T1 / c.T0 > 1.9);  // the wall did heat it: (1 / 0.7)^2 = 2.04
}

TEST_CASE("Moving wall: the energy changes by the summed per-hit wall work, to rounding") {
  for (double J : {0.0, 1.0}) {
    CAPTURE(J);
    const Cycle c = run_moves(free_gas(200, 5, J), {{0.8, 0.2}, {1.0, 0.2}}, 1e-3);
    CHECK(c.work != 0);
    CHECK(std::abs((c.E1 - c.E0) - c.work) <= 1e-9 * std::abs(c.E0));
  }
}

TEST_CASE("Moving wall: a compress-expand cycle at finite speed heats the gas (hysteresis)") {
  // A quasi-static cycle returns to its start; at a wall speed comparable to the thermal
  // speed the compression is harder than the expansion gives back, so net work is done.
  const Cycle slow = run_moves(free_gas(300, 7), {{0.6, 0.01}, {1.0, 0.01}}, 2e-3);
  const Cycle fast = run_moves(free_gas(300, 7), {{0.6, 1.0}, {1.0, 1.0}}, 1e-3);
  CAPTURE(slow.T1 / slow.T0);
  CAPTURE(fast.T1 / fast.T0);
  CHECK(slow.T1 / slow.T0 == doctest::Approx(1.0).epsilon(0.03));
  CHECK(fast.work > 0);
  CHECK(fast.T1 / fast.T0 > 1.05);
  CHECK(fast.T1 / fast.T0 > slow.T1 / slow.T0 + 0.03);
}

TEST_CASE("a moving-wall run ends in the pinned state (native == wasm)") {
  // In and out at a tenth of the thermal speed, J > 0, on both engines.
  System s = free_gas(300, 9, 1.0 / 300);
  EngineConfig config;
  config.container_radius = 1.0;
  config.wall_moves = {{0.8, 0.1}, {1.0, 0.1}};
  const std::uint64_t reference =
      testing::final_state_hash(*make_reference_engine(s, config), 3000, 1e-3, 500);
  const std::uint64_t fast = testing::final_state_hash(*make_engine(s, config), 3000, 1e-3, 500);
  INFO("hashes ", reference, " ", fast);
  CHECK(reference == 0x5d30ad5555714d90ULL);
  CHECK(fast == 0x0314272b813094caULL);  // make_engine: the fast engine
}
