#include <doctest/doctest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "swarm/engine/engine.h"
#include "swarm/measure/state_hash.h"
#include "swarm/methods/integrators.h"
#include "swarm/physics/diagnostics.h"
#include "swarm/run/side_by_side.h"
#include "test_systems.h"

using namespace swarm;
using doctest::Approx;

namespace {

using testing::crowded_swarm;

/// The billiard path of one free particle in a sphere, by ray-sphere intersection.
Vec3 billiard(Vec3 p, Vec3 v, double R, double T) {
  double t = 0;
  for (;;) {
    const double b = p.dot(v), vv = v.squaredNorm();
    const double to_wall = (-b + std::sqrt(b * b - vv * (p.squaredNorm() - R * R))) / vv;
    if (t + to_wall >= T) return p + v * (T - t);
    p += v * to_wall;
    t += to_wall;
    const Vec3 n = p / R;
    v -= 2 * v.dot(n) * n;
  }
}

}  // namespace

TEST_CASE("energy is conserved in a fixed container to 1e-10 over 100,000 steps") {
  testing::check_energy_kept_in_fixed_container(make_reference_engine);
}

TEST_CASE("exact collisions conserve energy too and keep every particle inside the wall") {
  for (double sign : {+1.0, -1.0}) {
    const System s = crowded_swarm(60, sign, 8);
    auto engine = make_reference_engine(s, {Method::analytic, CollisionMode::exact, 1.0});
    const double E0 = total_energy(s);
    for (int i = 0; i < 20000; ++i) {
      engine->step(1e-3);
      for (const auto& p : engine->system().particles) REQUIRE(p.r.norm() < 1 + 1e-9);
    }
    CHECK(std::abs(total_energy(engine->system()) - E0) / std::abs(E0) < 1e-10);
  }
}

TEST_CASE("the momentum given to the wall equals the system's loss of momentum") {
  for (CollisionMode mode : {CollisionMode::paper, CollisionMode::exact}) {
    const System s = crowded_swarm(80, 1.0, 4);
    auto engine = make_reference_engine(s, {Method::analytic, mode, 1.0});
    testing::check_wall_takes_lost_momentum(*engine, s);
  }
}

TEST_CASE("one free particle: exact collisions follow the billiard, the paper's err O(dt)") {
  System s;
  s.J = 0;
  s.particles = {{1.0, {0.3, -0.2, 0.1}, {0.9, 0.7, -0.4}}};
  const double T = 10, R = 1;
  const Vec3 truth = billiard(s.particles[0].r, s.particles[0].v, R, T);
  auto run = [&](CollisionMode mode, int steps) {
    auto e = make_reference_engine(s, {Method::analytic, mode, R});
    for (int i = 0; i < steps; ++i) e->step(T / steps);
    return (e->system().particles[0].r - truth).norm();
  };
  CHECK(run(CollisionMode::exact, 1000) < 1e-10);
  CHECK(run(CollisionMode::exact, 137) < 1e-10);
  const double coarse = run(CollisionMode::paper, 10000), fine = run(CollisionMode::paper, 20000);
  CHECK(coarse > 1e-5);
  CHECK(std::log2(coarse / fine) == Approx(1.0).epsilon(0.25));
}

TEST_CASE("an ideal gas (J = 0) obeys P V = 2 KE / 3 and its wall temperature is T") {
  SwarmSpec spec;
  spec.count = 1000;
  spec.mass_min = 4;
  spec.mass_max = 5;
  spec.position_radius = 1;
  spec.velocities = SwarmSpec::Velocities::maxwell;
  spec.temperature = 2.0;
  spec.seed = 17;
  System s = generate_swarm(spec);
  s.J = 0;
  const double KE = kinetic_energy(s), R = 1, dt = 2e-3;
  auto engine = make_reference_engine(s, {Method::analytic, CollisionMode::exact, R});
  double impulse = 0, hit_ke = 0;
  long hits = 0;
  const int steps = 20000;
  for (int i = 0; i < steps; ++i) {
    const WallTally w = engine->step(dt);
    impulse += w.radial_impulse;
    hit_ke += w.hit_kinetic_energy;
    hits += w.hits;
  }
  const double P = impulse / (sphere_area(R) * steps * dt);
  CHECK(P * sphere_volume(R) == Approx(2 * KE / 3).epsilon(0.02));
  // Hitters are weighted by speed: for a Maxwellian their mean kinetic energy is 2 T.
  const double T_sample = 2 * KE / (3 * spec.count);
  CHECK(0.5 * hit_ke / hits == Approx(T_sample).epsilon(0.05));
}

TEST_CASE("a numerical method in a container follows Appendix A with its own trajectories") {
  // Appendix A spelled out with Verlet as the trajectory map: predict with a Verlet step,
  // reflect the predicted leavers that move outward at their present position, then step.
  const System s = crowded_swarm(30, 1.0, 2);
  auto engine = make_reference_engine(s, {Method::verlet, CollisionMode::paper, 1.0});
  System by_hand = s;
  long hits = 0;
  for (int i = 0; i < 3000; ++i) {
    System predicted = by_hand;
    step_verlet(predicted, 1e-3);
    WallTally expected;
    for (std::size_t k = 0; k < by_hand.particles.size(); ++k) {
      Particle& p = by_hand.particles[k];
      if (predicted.particles[k].r.norm() > 1.0 && p.v.dot(p.r) > 0) reflect_at_wall(p, expected);
    }
    step_verlet(by_hand, 1e-3);
    const WallTally got = engine->step(1e-3);
    REQUIRE(got.hits == expected.hits);
    hits += got.hits;
  }
  CHECK(hits > 20);
  CHECK(max_position_difference(engine->system(), by_hand) < 1e-12);
  // Verlet's energy error is O((omega dt)^2) = 1e-6 here; reflections keep kinetic energy.
  CHECK(total_energy(engine->system()) == Approx(total_energy(s)).epsilon(1e-5));
  CHECK_THROWS(make_reference_engine(s, {Method::rk4, CollisionMode::exact, 1.0}));
}

TEST_CASE("the reference engine gives the same run on any number of threads") {
  // 1000 particles in a wall: the pairwise forces of every method run on threads in ten
  // blocks of rows, combined in block order. Each step's tally and the final state must be
  // the same to the last bit for 1 to 7 threads (more than this machine's cores).
  const System s = crowded_swarm(1000, 1.0, 17);
  for (const Method method : {Method::euler, Method::euler_cromer, Method::verlet, Method::rk4}) {
    CAPTURE(name_of(method));
    const auto run = [&](int threads) {
      EngineConfig config{method, CollisionMode::paper, 0.8};
      config.threads = threads;
      auto engine = make_reference_engine(s, config);
      std::vector<double> tallies;
      for (int i = 0; i < 6; ++i) {
        const WallTally t = engine->step(2e-3);
        tallies.insert(tallies.end(), {double(t.hits), t.radial_impulse, t.hit_kinetic_energy,
                                       t.wall_momentum.x(), t.wall_momentum.y(),
                                       t.wall_momentum.z()});
      }
      return std::pair{state_hash(engine->system()), tallies};
    };
    const auto one = run(1);
    CHECK(one.second[0] > 0);  // the wall is hit in the first step
    for (const int threads : {2, 3, 4, 7}) {
      CAPTURE(threads);
      const auto other = run(threads);
      CHECK(other.first == one.first);
      CHECK(other.second == one.second);
    }
  }
}
