#include "swarm/run/side_by_side.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "swarm/methods/integrators.h"
#include "test_systems.h"

using namespace swarm;
using swarm::testing::two_body_circle;

namespace {

RunPlan isolated_plan(Method primary, long steps, long sample_every, double dt) {
  RunPlan plan;
  plan.engine.method = primary;
  plan.dt = dt;
  plan.steps = steps;
  plan.sample_every = sample_every;
  return plan;
}

/// The largest distance between the same particle in two systems, written out here.
double largest_distance(const System& a, const System& b) {
  double worst = 0;
  for (std::size_t i = 0; i < a.particles.size(); ++i) {
    const Vec3 d = a.particles[i].r - b.particles[i].r;
    worst = std::max(worst, std::sqrt(d.x() * d.x() + d.y() * d.y() + d.z() * d.z()));
  }
  return worst;
}

}  // namespace

TEST_CASE("compared methods start from the same state and stay in lockstep") {
  const System s = testing::four_masses(0.5);
  SideBySide runs(s, isolated_plan(Method::verlet, 100, 10, 0.01), {Method::euler, Method::rk4});
  REQUIRE(runs.tracks().size() == 2);
  for (const auto& track : runs.tracks()) {
    const System& start = track.run->engine().system();
    CHECK(start.t == s.t);
    for (std::size_t i = 0; i < s.particles.size(); ++i) {
      CHECK(start.particles[i].r == s.particles[i].r);
      CHECK(start.particles[i].v == s.particles[i].v);
    }
    CHECK(track.samples.front().position_error == 0);
  }
  CHECK(runs.advance(37) == 37);
  for (const auto& track : runs.tracks())
    CHECK(track.run->engine().system().t == runs.primary().engine().system().t);
  runs.finish();
  const auto& primary_samples = runs.primary().samples();
  for (const auto& track : runs.tracks()) {
    REQUIRE(track.samples.size() == primary_samples.size());
    for (std::size_t k = 0; k < primary_samples.size(); ++k)
      CHECK(track.samples[k].t == primary_samples[k].t);
  }
  CHECK(runs.advance(5) == 0);  // the run is over
}

TEST_CASE("position_error is max |r_a - r_b| of the methods stepped independently") {
  const System s = testing::four_masses(0.5);
  const double dt = 0.02;
  SideBySide runs(s, isolated_plan(Method::euler_cromer, 60, 20, dt), {Method::euler});
  runs.finish();
  System cromer = s, euler = s;
  const auto& samples = runs.tracks()[0].samples;
  REQUIRE(samples.size() == 4);
  for (int k = 1; k <= 3; ++k) {
    for (int i = 0; i < 20; ++i) step_euler_cromer(cromer, dt), step_euler(euler, dt);
    const double expected = largest_distance(euler, cromer);
    CHECK(expected > 1e-4);  // the two have parted measurably
    CHECK(samples[std::size_t(k)].position_error == doctest::Approx(expected).epsilon(1e-12));
  }
}

TEST_CASE("the analytic solution compared with itself has no error") {
  const System s = testing::four_masses(0.5);
  SideBySide runs(s, isolated_plan(Method::analytic, 200, 10, 0.05), {Method::analytic});
  runs.finish();
  for (const ComparisonSample& c : runs.tracks()[0].samples) CHECK(c.position_error == 0);
  CHECK(runs.exact() == &runs.primary());
  CHECK(runs.errors_from_exact().empty());  // no numerical method to measure
}

TEST_CASE("errors from the exact solution: every numerical run against a compared analytic one") {
  const System s = two_body_circle();
  const double dt = 0.01, w = std::sqrt(2.0);
  SideBySide runs(s, isolated_plan(Method::euler, 300, 100, dt),
                  {Method::verlet, Method::analytic});
  REQUIRE(runs.exact() == runs.tracks()[1].run.get());
  runs.finish();
  const auto& errors = runs.errors_from_exact();
  REQUIRE(errors.size() == 2);
  CHECK(errors[0].method == Method::euler);  // the primary first
  CHECK(errors[1].method == Method::verlet);
  // Euler by hand against the closed-form circle: both particles are symmetric, so the error
  // is particle 0's distance from (cos, sin) / 2.
  System euler = s;
  REQUIRE(errors[0].t.size() == 4);
  CHECK(errors[0].position_error[0] == 0);
  for (int k = 1; k <= 3; ++k) {
    for (int i = 0; i < 100; ++i) step_euler(euler, dt);
    const double t = dt * 100 * k;
    const Vec3 exact(0.5 * std::cos(w * t), 0.5 * std::sin(w * t), 0);
    CHECK(errors[0].t[std::size_t(k)] == doctest::Approx(t));
    CHECK(errors[0].position_error[std::size_t(k)] ==
          doctest::Approx((euler.particles[0].r - exact).norm()).epsilon(1e-9));
  }
  // Verlet is second order, Euler first: at dt = 0.01 Verlet is much closer.
  CHECK(errors[1].position_error.back() < 0.01 * errors[0].position_error.back());
}

TEST_CASE("scaling the container grows every run's wall at once") {
  const System s = testing::random_swarm(20, 1.0, 4, 0.5, 0.5);
  RunPlan plan = isolated_plan(Method::analytic, 10, 1, 1e-3);
  plan.engine.container_radius = 1.0;
  SideBySide runs(s, plan, {Method::rk4});
  runs.scale_container(1.5);
  CHECK(*runs.primary().engine().container_radius() == 1.5);
  CHECK(*runs.tracks()[0].run->engine().container_radius() == 1.5);
}
