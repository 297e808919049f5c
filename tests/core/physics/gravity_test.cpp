#include <doctest/doctest.h>

#include <cmath>

#include "swarm/engine/engine.h"
#include "swarm/engine/fast_engine.h"
#include "swarm/physics/analytic.h"
#include "swarm/physics/gravity.h"
#include "test_systems.h"

using namespace swarm;

namespace {

/// Largest |r_i - r_i(closed form)| / max(1, |r_i(closed form)|) after `steps` steps of dt
/// under gravity g, where the closed form is the paper's solution of the isolated swarm with
/// its CM falling freely: R_cm = R0 + V0 t + g t^2 / 2, the motion about the CM unchanged.
double worst_relative_error(const System& initial, Method m, const Vec3& g, long steps, double dt) {
  EngineConfig config;
  config.method = m;
  config.forces.gravity = g;
  auto engine = make_engine(initial, config);
  for (long i = 0; i < steps; ++i) engine->step(dt);
  const double t = engine->time();
  const System expected = AnalyticSolution(initial).at(t);
  double worst = 0;
  for (std::size_t i = 0; i < initial.particles.size(); ++i) {
    const Vec3 r = expected.particles[i].r + 0.5 * g * t * t;
    const Vec3 v = expected.particles[i].v + g * t;
    const Particle& p = engine->system().particles[i];
    worst = std::max(worst, (p.r - r).norm() / std::max(1.0, r.norm()));
    worst = std::max(worst, (p.v - v).norm() / std::max(1.0, v.norm()));
  }
  return worst;
}

}  // namespace

TEST_CASE("gravity: U_g = -sum m g.r, zero at the origin") {
  System s;
  s.particles = {{2.0, {1, 2, 3}, {0, 0, 0}}, {0.5, {0, 0, -4}, {1, 0, 0}}};
  CHECK(gravity_potential_energy(s, Vec3(0, 0, -9.8)) == doctest::Approx(2 * 9.8 * 3 - 0.5 * 9.8 * 4));
}

TEST_CASE("gravity without a floor: the CM falls freely and the motion about it is the paper's") {
  const Vec3 g(0.3, -0.2, -9.8);
  for (double J : {1.0, 0.0, -0.3}) {
    CAPTURE(J);
    const System s = testing::four_masses(J);
    // The exact map with gravity's g t^2 / 2: rounding only, over 3,000 steps.
    CHECK(worst_relative_error(s, Method::analytic, g, 3000, 1e-3) < 1e-9);
    // RK4 through the pairwise forces plus g: its own error at dt = 1e-3 is far below 1e-9.
    CHECK(worst_relative_error(s, Method::rk4, g, 3000, 1e-3) < 1e-9);
  }
}

TEST_CASE("gravity and mass-proportional drag stay on the fast engine; drag on chosen particles does not") {
  EngineConfig config;
  CHECK(fast_engine_applies(config));
  config.forces.gravity = Vec3(0, 0, -1);
  CHECK(fast_engine_applies(config));
  config.forces.drag = Drag{0.5, 0, {}};
  CHECK(fast_engine_applies(config));
  config.floor = Floor{-2, 1};
  CHECK(fast_engine_applies(config));
  config.floor = Floor{-2, 0.5};  // particles come to rest on an inelastic floor
  CHECK_FALSE(fast_engine_applies(config));
  config.floor.reset();
  config.forces.drag = Drag{0, 0.5, {1}};
  CHECK_FALSE(fast_engine_applies(config));
}
