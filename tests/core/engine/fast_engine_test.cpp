#include "swarm/engine/fast_engine.h"

#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <vector>

#include "swarm/engine/engine.h"
#include "swarm/measure/state_hash.h"
#include "swarm/methods/integrators.h"
#include "swarm/physics/analytic.h"
#include "swarm/physics/diagnostics.h"
#include "swarm/physics/gravity.h"
#include "core/engine/engines_side_by_side.h"
#include "swarm/preset/preset.h"
#include "test_systems.h"

using namespace swarm;
using doctest::Approx;
using testing::crowded_swarm;
using testing::require_same_run;
using testing::SideBySideRun;
using testing::max_state_difference;
using testing::shipped_preset;

namespace {

void require_same_run(const System& s, double R, double dt, int steps) {
  const long hits =
      testing::require_same_run(s, EngineConfig{Method::analytic, CollisionMode::paper, R}, dt, steps)
          .hits;
  CHECK(hits > steps / 4);
}

}  // namespace

TEST_CASE("the fast engine hits the wall exactly when the reference engine does") {
  SUBCASE("attractive") { require_same_run(crowded_swarm(2000, +1.0, 3), 1.0, 1e-3, 4000); }
  SUBCASE("repulsive") { require_same_run(crowded_swarm(2000, -1.0, 5), 1.0, 1e-3, 4000); }
  SUBCASE("J = 0") { require_same_run(crowded_swarm(2000, 0.0, 7), 1.0, 1e-3, 4000); }
  SUBCASE("coarse steps") { require_same_run(crowded_swarm(2000, +1.0, 9), 1.0, 1e-2, 3000); }
}

TEST_CASE("under gravity and drag the fast engine hits the wall when the reference engine does") {
  // Gravity moves only the CM, along a parabola; mass-proportional drag makes every particle
  // a damped oscillator about a decaying CM motion (Appendix B). J < 0 runs shorter: its
  // runaway presses the swarm against the wall within a few time units.
  const auto config = [](const Vec3& g, double gamma) {
    EngineConfig c{Method::analytic, CollisionMode::paper, 1.0};
    c.forces.gravity = g;
    if (gamma > 0) c.forces.drag = Drag{gamma, 0, {}};
    return c;
  };
  const Vec3 g(0.1, 0, -0.6);
  for (double sign : {+1.0, 0.0, -1.0}) {
    CAPTURE(sign);
    const int steps = sign < 0 ? 800 : 3000;
    const System s = crowded_swarm(2000, sign, 41);
    SUBCASE("gravity") { CHECK(require_same_run(s, config(g, 0), 1e-3, steps).hits > steps); }
    SUBCASE("drag") {
      CHECK(require_same_run(s, config(Vec3::Zero(), 0.4), 1e-3, steps).hits > steps / 4);
    }
    SUBCASE("drag and gravity") {
      CHECK(require_same_run(s, config(g, 0.4), 1e-3, steps).hits > steps / 4);
    }
    SUBCASE("gravity and a floor") {
      EngineConfig c = config(g, 0);
      c.floor = Floor{-0.5, 1};
      const SideBySideRun run = require_same_run(s, c, 1e-3, steps);
      CHECK(run.hits > steps / 2);
      CHECK(run.floor_hits > steps / 2);
    }
    SUBCASE("drag, gravity and a floor") {
      EngineConfig c = config(g, 0.4);
      c.floor = Floor{-0.3, 1};
      CHECK(require_same_run(s, c, 1e-3, steps).floor_hits > steps / 2);
    }
    SUBCASE("over-damped drag") {
      CHECK(require_same_run(s, config(g, 5.0), 1e-3, steps).hits > 100);
    }
  }
}

TEST_CASE("under gravity the anchors' forecast takes in the wall's mean push on the CM") {
  // The swarm, pressed on the wall, is held up by it: over 25 time units the wall's kicks add
  // up to the CM's change of velocity less g t. The engine's running mean of the push (what its
  // forecast of the CM uses), averaged over the same steps, must agree, sign and size, with
  // that sum taken from the particles' momenta.
  const System s = crowded_swarm(2000, 1.0, 47);
  EngineConfig c{Method::analytic, CollisionMode::paper, 1.0};
  c.forces.gravity = Vec3(0.1, 0, -0.6);
  auto engine = make_fast_engine(s, c);
  const double dt = 1e-2;
  const auto cm_velocity = [](const System& now) {
    Vec3 p = Vec3::Zero();
    for (const Particle& q : now.particles) p += q.m * q.v;
    return Vec3(p / total_mass(now));
  };
  for (int i = 0; i < 500; ++i) engine->step(dt);
  const Vec3 v0 = cm_velocity(engine->system());
  Vec3 mean_push = Vec3::Zero();
  constexpr int kSteps = 2500;
  for (int i = 0; i < kSteps; ++i) {
    engine->step(dt);
    mean_push += fast_engine_stats(*engine)->wall_push / kSteps;
  }
  const Vec3 held = (cm_velocity(engine->system()) - v0) / (kSteps * dt) - c.forces.gravity;
  CAPTURE(held.transpose());
  CAPTURE(mean_push.transpose());
  CHECK(held.z() > 0.3);  // the wall holds the swarm up against g_z = -0.6
  CHECK((mean_push - held).norm() < 0.1 * c.forces.gravity.norm());
}

TEST_CASE("under strong gravity a loose swarm hits the wall when the reference engine does") {
  // g = 9.8 in the unit sphere with J = 0 (free particles) or a weak pull (omega = 0.1): the
  // CM's parabola bends by g h^2 / 2, about 8 R, over an anchor's horizon h, far more than an
  // anchor's margin can hold (the engine then shortens the horizon: at J = 0 main's engine hit
  // the wall differently from the 8th step on). 400 steps: the swarm, pressed on the wall,
  // bounces every few steps, and the two engines' rounding would part later.
  for (double J : {0.0, 0.01}) {
    CAPTURE(J);
    System s = crowded_swarm(2000, 1.0, 43);
    s.J *= J;
    EngineConfig c{Method::analytic, CollisionMode::paper, 1.0};
    c.forces.gravity = Vec3(0.1, 0, -9.8);
    SUBCASE("the wall") { CHECK(require_same_run(s, c, 1e-2, 400).hits > 10000); }
    SUBCASE("the wall and a floor") {
      c.floor = Floor{-0.5, 1};
      const SideBySideRun run = require_same_run(s, c, 1e-2, 400);
      CHECK(run.hits > 1000);
      CHECK(run.floor_hits > 10000);
    }
  }
}

TEST_CASE("the fast engine drops the shipped swarm on its floor as the reference engine does") {
  // No container: the floor is the only wall. 4,000 steps take the swarm through its first
  // bounces.
  const Preset preset = shipped_preset("gravity-floor-bounce.json");
  const EngineConfig config = run_plan(preset).engine;
  REQUIRE(fast_engine_applies(config));
  const SideBySideRun run = require_same_run(initial_system(preset), config, preset.dt, 4000);
  CHECK(run.hits == 0);
  CHECK(run.floor_hits > 100);
}

TEST_CASE("the fast engine reproduces the reference on the shipped expansion presets") {
  for (const char* name : {"fig2-attractive-expansion.json", "fig3-repulsive-fireball.json"}) {
    CAPTURE(name);
    Preset preset = shipped_preset(name);
    std::get<SwarmSpec>(preset.particles).count = 2000;
    preset.J *= 2;  // the same omega with half the particles
    // Three stages of the expansion, 300 steps each: wall moves included.
    preset.expansion->tau = 300 * preset.dt;
    preset.expansion->stages = 3;
    const RunPlan plan = run_plan(preset);
    Run reference(make_reference_engine(initial_system(preset), plan.engine), plan);
    Run fast(make_fast_engine(initial_system(preset), plan.engine), plan);
    while (!reference.finished()) {
      reference.advance(1);
      fast.advance(1);
      REQUIRE(reference.samples().back().hits == fast.samples().back().hits);
    }
    fast.finish();
    REQUIRE(reference.stages().size() == fast.stages().size());
    for (std::size_t i = 0; i < reference.stages().size(); ++i) {
      CHECK(fast.stages()[i].hits == reference.stages()[i].hits);
      CHECK(fast.stages()[i].P == Approx(reference.stages()[i].P).epsilon(1e-10));
      CHECK(fast.stages()[i].T == Approx(reference.stages()[i].T).epsilon(1e-10));
    }
    CHECK(fast.summary().wall_hits == reference.summary().wall_hits);
    CHECK(max_state_difference(reference.engine().system(), fast.engine().system()) < 1e-9);
  }
}

TEST_CASE("the fast engine conserves energy to 1e-10 over 100,000 steps in a fixed container") {
  testing::check_energy_kept_in_fixed_container(make_fast_engine);
}

TEST_CASE("the fast engine gives the wall the momentum the system loses") {
  const System s = crowded_swarm(300, -1.0, 4);
  auto engine = make_fast_engine(s, {Method::analytic, CollisionMode::paper, 1.0});
  testing::check_wall_takes_lost_momentum(*engine, s);
}

TEST_CASE("an isolated system in the fast engine follows the analytic solution") {
  for (double J : {+1.0, -1.0, 0.0}) {
    CAPTURE(J);
    const System s = testing::four_masses(J * 0.1);
    auto engine = make_fast_engine(s, {Method::analytic, CollisionMode::paper, std::nullopt});
    for (int i = 0; i < 3000; ++i) engine->step(1e-2);
    const System truth = AnalyticSolution(s).at(30.0);
    CHECK(engine->time() == Approx(30.0));
    for (std::size_t i = 0; i < s.particles.size(); ++i) {
      const double scale = 1 + truth.particles[i].r.norm() + truth.particles[i].v.norm();
      CHECK((engine->system().particles[i].r - truth.particles[i].r).norm() < 1e-10 * scale);
      CHECK((engine->system().particles[i].v - truth.particles[i].v).norm() < 1e-10 * scale);
    }
  }
}

TEST_CASE("the fast engine only checks particles that can reach the wall") {
  // A large swarm with a few hundred hits per step must not touch every particle every step.
  const System s = crowded_swarm(20000, -1.0, 11, 1.0);
  auto engine = make_fast_engine(s, {Method::analytic, CollisionMode::paper, 1.0});
  for (int i = 0; i < 2000; ++i) engine->step(1e-2);
  const FastEngineStats stats = *fast_engine_stats(*engine);
  CHECK(stats.hits > 2000 * 50);
  CHECK(double(stats.checks + stats.expired) < 0.1 * 20000.0 * 2000.0);
}

TEST_CASE("the fast engine's wall hits do not bias the energy (repulsive, 100,000 steps)") {
  // A hit's velocity jump goes through the flow's determinant cosh^2 - sinh^2, which rounds
  // to 1 + O(1e-15) with a sign of its own; uncorrected, 3.7 million hits drift by 2.4e-10.
  System s = testing::random_swarm(4000, 1.0, 2025, 1.0, 1.0);
  s.J = -1.0 / total_mass(s);
  auto engine = make_fast_engine(s, {Method::analytic, CollisionMode::paper, 1.0});
  const double E0 = total_energy(s);
  long hits = 0;
  for (int i = 0; i < 100000; ++i) hits += engine->step(1e-2).hits;
  CHECK(hits > 3000000);
  CHECK(std::abs(total_energy(engine->system()) - E0) / std::abs(E0) < 5e-11);
}

TEST_CASE("the fast engine follows changes of dt and of the wall like the reference") {
  for (double sign : {+1.0, -1.0}) {
    CAPTURE(sign);
    const System s = crowded_swarm(500, sign, 13);
    const EngineConfig config{Method::analytic, CollisionMode::paper, 1.0};
    auto reference = make_reference_engine(s, config);
    auto fast = make_fast_engine(s, config);
    for (int i = 0; i < 3000; ++i) {
      if (i % 500 == 250) {  // grow, shrink, remove and restore the wall
        const std::optional<double> R =
            i == 1250 ? std::nullopt : std::optional<double>(0.9 + 0.05 * (i % 1000 == 250));
        reference->set_container_radius(R);
        fast->set_container_radius(R);
      }
      const double dt = i % 700 < 350 ? 1e-3 : 2.5e-3;
      REQUIRE(reference->step(dt).hits == fast->step(dt).hits);
    }
    CHECK(max_state_difference(reference->system(), fast->system()) < 1e-9);
  }
}

TEST_CASE("any thread count gives the same run to the last bit") {
  // A step's hits are combined in particle-id order and the epoch's sums in fixed blocks, so
  // neither the number of lanes (one per thread) nor which thread ran one may show at all:
  // not in the final state, not in any step's tally, not in the work done. 7 threads are more
  // than this machine's cores. In the browser the lanes run one after the other, which still
  // checks that their number changes nothing.
  struct Run {
    std::uint64_t state = 0;
    std::vector<double> tallies;  // every step's tally, in order
    std::int64_t hits = 0, checks = 0, rebases = 0, reschedules = 0, expired = 0;
  };
  const auto run = [](const System& s, int threads, bool forced, bool drag) {
    EngineConfig config{Method::analytic, CollisionMode::paper, 1.0};
    config.threads = threads;
    if (forced) {  // the drag's energy sums and the floor's bounces are combined the same way
      config.forces.gravity = Vec3(0.1, 0, -0.6);
      if (drag) config.forces.drag = Drag{0.4, 0, {}};  // without: off-centre anchors
      config.floor = Floor{-0.5, 1};
    }
    auto engine = make_fast_engine(s, config);
    Run r;
    for (int i = 0; i < 1500; ++i) {
      if (i == 700) engine->set_container_radius(0.95);  // every particle rescheduled
      const WallTally t = engine->step(i < 1000 ? 1e-3 : 1.5e-3);
      r.hits += t.hits;
      r.tallies.insert(r.tallies.end(),
                       {double(t.hits), double(t.floor_hits), t.radial_impulse, t.hit_kinetic_energy,
                        t.wall_momentum.x(), t.wall_momentum.y(), t.wall_momentum.z(),
                        t.books.net()});
    }
    r.state = state_hash(engine->system());
    const FastEngineStats stats = *fast_engine_stats(*engine);
    r.checks = stats.checks;
    r.rebases = stats.rebases;
    r.reschedules = stats.reschedules;
    r.expired = stats.expired;
#ifndef __EMSCRIPTEN__
    // More than one thread really did share the steps, and one alone did not.
    if (threads > 1)
      CHECK(stats.parallel_steps > 500);
    else
      CHECK(stats.parallel_steps == 0);
#endif
    return r;
  };
  // 10,000 particles: the epoch's sums span three blocks of 4096.
  struct Setup {
    double J;
    bool forced, drag;
  };
  for (const Setup& setup : {Setup{+1.0, false, false}, Setup{-1.0, false, false},
                             Setup{0.0, false, false}, Setup{+1.0, true, true},
                             Setup{+1.0, true, false}}) {
    // Not a structured binding: CAPTURE's lambda may not name one in C++17 (clang, emcc).
    const double J = setup.J;
    const bool forced = setup.forced, drag = setup.drag;
    CAPTURE(J);
    CAPTURE(forced);
    CAPTURE(drag);
    System s = crowded_swarm(10000, J, 31);
    if (J == 0) s.J = 0;
    const Run one = run(s, 1, forced, drag);
    CHECK(one.hits > 1000);
    CHECK(one.rebases > 0);
    for (const int threads : {2, 3, 4, 7}) {
      CAPTURE(threads);
      const Run other = run(s, threads, forced, drag);
      CHECK(other.state == one.state);
      CHECK(other.tallies == one.tallies);
      CHECK(other.hits == one.hits);
      CHECK(other.checks == one.checks);
      CHECK(other.rebases == one.rebases);
      CHECK(other.reschedules == one.reschedules);
      CHECK(other.expired == one.expired);
    }
  }
}
