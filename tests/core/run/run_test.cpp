#include "swarm/run/run.h"

#include <doctest/doctest.h>

#include <cmath>

#include "swarm/measure/speed_distribution.h"
#include "swarm/physics/diagnostics.h"
#include "swarm/preset/initial_conditions.h"
#include "test_systems.h"

using namespace swarm;
using doctest::Approx;

TEST_CASE("the expansion protocol: radius steps, averaging windows, energy kept") {
  System s = testing::random_swarm(300, 1.0, 9, 1.0, 1.5);
  s.J = -1.0 / total_mass(s);
  RunPlan plan;
  plan.engine = {Method::analytic, CollisionMode::paper, 1.0};
  plan.dt = 1e-3;
  plan.expansion = ExpansionProtocol{1.2, 5, 0.5, 0.8};
  plan.steps = 5 * steps_per_stage(*plan.expansion, plan.dt);
  plan.sample_every = 50;
  Run run(s, plan);
  run.finish();
  REQUIRE(run.stages().size() == 5);
  for (std::size_t k = 0; k < 5; ++k) {
    const Stage& st = run.stages()[k];
    CHECK(st.R == Approx(std::pow(1.2, double(k))));
    CHECK(st.V == Approx(4.0 / 3.0 * M_PI * std::pow(st.R, 3)));
    CHECK(st.P > 0);
    CHECK(st.T > 0);
    CHECK(st.E == Approx(total_energy(s)).epsilon(1e-11));
  }
  // Repulsive: the wall temperature rises and the pressure falls as the volume grows.
  CHECK(run.stages().back().T > run.stages().front().T);
  CHECK(run.stages().back().P < run.stages().front().P);
  CHECK(run.samples().size() == 1 + 2500 / 50);
  CHECK(run.summary().steps == 2500);
  CHECK(std::abs(run.summary().energy_drift) < 1e-11);
  CHECK(run.samples().back().t == Approx(2.5));
}

TEST_CASE("a stage's T kinetic is (2/3) KE / N averaged over its window, not its end") {
  // omega = 1 and a start far from the virial balance: KE breathes at 2 omega (period pi).
  System s = testing::crowded_swarm(300, 1.0, 4);
  RunPlan plan;
  plan.engine = {Method::analytic, CollisionMode::paper, 1.0};
  plan.dt = 1e-3;
  plan.expansion = ExpansionProtocol{1.0, 1, 40.0, 0.5};  // window: the last 20 time units
  plan.steps = 40000;
  Run run(s, plan);
  run.finish();
  // By hand with a second engine: the exact two-pass kinetic_temperature at every step.
  auto engine = make_engine(s, plan.engine);
  double sum = 0, lowest = 1e300, highest = 0;
  for (int i = 0; i < 40000; ++i) {
    engine->step(1e-3);
    if (i < 20000) continue;
    const double T = kinetic_temperature(engine->system());
    sum += T, lowest = std::min(lowest, T), highest = std::max(highest, T);
  }
  const double mean = sum / 20000, T_end = kinetic_temperature(engine->system());
  // Measured: 2.05117 by hand, 2.05109 the stage's, 2.01797 at the end; swing 0.134.
  const double tolerance = 0.02 * (highest - lowest);
  CHECK(std::abs(run.stages()[0].T_kinetic - mean) < tolerance);
  CHECK(std::abs(T_end - mean) > 5 * tolerance);  // the end alone would not do
}

TEST_CASE("stage averages are the pressure over the last 20% of each stage") {
  System s = testing::random_swarm(100, 1.0, 2, 1.0, 1.5);
  s.J = 1.0 / total_mass(s);
  RunPlan plan;
  plan.engine = {Method::analytic, CollisionMode::paper, 1.0};
  plan.dt = 1e-3;
  plan.expansion = ExpansionProtocol{1.0, 1, 1.0, 0.8};
  plan.steps = 1000;
  Run run(s, plan);
  run.finish();
  // The same window measured by hand with a second engine.
  auto engine = make_engine(s, plan.engine);
  double impulse = 0;
  for (int i = 0; i < 1000; ++i) {
    const WallTally w = engine->step(1e-3);
    if (i >= 800) impulse += w.radial_impulse;
  }
  CHECK(run.stages()[0].P == Approx(impulse / (4 * M_PI * 0.2)));
}

TEST_CASE("a run whose energies overflow stops at the sample that shows it, naming E") {
  // Two unit masses at +-0.5 pushed apart (J = -1, Omega = sqrt 2): the energy grows as
  // exp(2 Omega t) and passes the largest double at Omega t ~ 355 (the preset rules refuse
  // this; a Run built in code is not checked, so this is the last line of defence).
  System s;
  s.J = -1;
  s.particles = {{1, {0.5, 0, 0}, {0, 0, 0}}, {1, {-0.5, 0, 0}, {0, 0, 0}}};
  RunPlan plan;
  plan.engine = {Method::analytic, CollisionMode::paper, std::nullopt};
  plan.dt = 1.0 / std::sqrt(2.0);  // Omega dt = 1
  plan.steps = 400;
  plan.sample_every = 1;
  Run run(s, plan);
  run.finish();
  CHECK(run.finished());
  // The first step whose energy is not finite: exp(2 Omega t) E0 passes 1.8e308 at Omega t ~ 355.
  CHECK(run.steps_done() >= 350);
  CHECK(run.steps_done() <= 360);
  CHECK(run.steps_done() < plan.steps);
  const std::string step = std::to_string(run.steps_done());
  CHECK(run.failure().rfind("step " + step + " (t = ", 0) == 0);
  CHECK(run.failure().find("is not finite") != std::string::npos);
  CHECK_FALSE(std::isfinite(run.samples().back().E));
  for (std::size_t i = 0; i + 1 < run.samples().size(); ++i)
    CHECK(std::isfinite(run.samples()[i].E));
  CHECK(run.advance(10) == 0);
}

TEST_CASE("a moving wall's P-V loop encloses exactly the work the wall's books record") {
  // P dV summed over the run is the work the gas does on the wall; each hit's work is
  // -u * (its radial impulse), so the two agree to rounding when P divides by the area the
  // wall swept in the step (with the area at either end they differ by O(u dt / R) a step).
  SwarmSpec spec;
  spec.count = 400;
  spec.position_radius = 0.95;
  spec.velocities = SwarmSpec::Velocities::maxwell;
  spec.temperature = 1;
  spec.cm_at_rest = true;
  spec.seed = 14;
  RunPlan plan;
  plan.engine.container_radius = 1.0;
  plan.engine.wall_moves = {{0.6, 0.5}, {1.0, 0.5}};
  plan.dt = 1e-3;
  plan.steps = 1800;
  plan.sample_every = 1;
  Run run(generate_swarm(spec), plan);
  run.finish();
  const std::vector<Sample>& samples = run.samples();
  double loop_area = 0;  // sum of P dV, the work done by the gas
  for (std::size_t i = 1; i < samples.size(); ++i)
    loop_area += samples[i].P * (sphere_volume(samples[i].R) - sphere_volume(samples[i - 1].R));
  const double booked = run.summary().books.wall_work;  // the work done on the gas
  REQUIRE(std::abs(booked) > 1e-3 * std::abs(run.summary().E0));
  CHECK(std::abs(loop_area + booked) <= 1e-9 * std::abs(booked));
}

TEST_CASE("hard spheres: the wall pressure divides by the sphere their centres reach") {
  // A sphere of radius a gives its impulse when its centre is at R - a: the same area as the
  // Carnahan-Starling check in docs/student-projects.md, so the read-out is that number.
  const System s = testing::random_swarm(300, 1.0, 4, 0.8, 2.0);
  RunPlan plan;
  plan.engine.container_radius = 1.0;
  plan.engine.sphere_radius = 0.05;
  plan.dt = 1e-3;
  plan.steps = 400;
  plan.sample_every = 400;
  Run run(s, plan);
  run.finish();
  auto engine = make_engine(s, plan.engine);
  double impulse = 0;
  for (int i = 0; i < 400; ++i) impulse += engine->step(1e-3).radial_impulse;
  REQUIRE(impulse > 0);
  CHECK(run.samples().back().P == Approx(impulse / (4 * M_PI * 0.95 * 0.95 * 0.4)).epsilon(1e-12));
}

TEST_CASE("hard spheres in an expansion: a stage's V is the ball their centres reach, as Carnahan-Starling needs") {
  // P divides by the area 4 pi (R - a)^2 where the centres give their impulse; the stage's V
  // is the same sphere's, 4/3 pi (R - a)^3 (with the container's 4/3 pi R^3 it was 17 % too
  // large here). Checked against the Carnahan-Starling equation of state at two packings (two
  // stages): P / (rho T) = Z_CS = (1 + eta + eta^2 - eta^3) / (1 - eta)^3, eta = rho 4/3 pi a^3,
  // with rho the density of the homogeneous gas, counted in the inner ball of radius
  // (R - a) / 2 over each stage's averaging window (the spheres pile up at the wall, so N / V
  // runs 5-10 % above it: docs/student-projects.md). With that V, N / V is the mean density
  // of the centres over the ball they reach, a little above the homogeneous gas's.
  const long N = 1500;
  const double a = std::cbrt(0.2 / double(N));  // eta = 0.2 in the ball of radius 1
  double spacing = 0;
  System s = testing::lattice_gas(N, 1.0 - 0.5 * a, 1.0, 31, &spacing);
  REQUIRE(spacing > 2 * a);
  RunPlan plan;
  plan.engine.container_radius = 1.0 + a;
  plan.engine.sphere_radius = a;
  plan.dt = 0.03 * a;  // a typical sphere moves 3 % of its radius in a step
  // Stage 2 at R' - a = 1.26: the packing falls by 1.26^3, to 0.1.
  const double factor = (1.26 + a) / (1.0 + a);
  // The lattice melts, and the gas fills the larger ball, in the first half of a stage; the
  // second half (2 time units) is averaged: the inner count over a shorter window scattered by
  // 5 % between builds whose last bits differ.
  plan.expansion = ExpansionProtocol{factor, 2, 4.0, 0.5};
  const long per_stage = steps_per_stage(*plan.expansion, plan.dt);
  plan.steps = 2 * per_stage;
  plan.sample_every = plan.steps;
  Run run(s, plan);
  // The inner ball's count, every 10 steps of each stage's averaging window (its second half).
  double inner[2] = {0, 0};
  long counts[2] = {0, 0};
  while (!run.finished()) {
    const long k = run.steps_done() / per_stage, in_stage = run.steps_done() % per_stage;
    if (in_stage >= per_stage / 2 && in_stage % 10 == 0) {
      const double half = 0.5 * (run.engine().container_radius().value() - a);
      for (const Particle& p : run.engine().system().particles) inner[k] += p.r.norm() < half;
      ++counts[k];
    }
    run.advance(1);
  }
  REQUIRE(run.stages().size() == 2);
  // J = 0 and elastic contacts: the kinetic energy is the whole energy and never changes.
  const double T = 2.0 / 3.0 * kinetic_energy(s) / double(N);
  for (std::size_t k = 0; k < 2; ++k) {
    const Stage& st = run.stages()[k];
    CAPTURE(k);
    CHECK(st.V == Approx(4.0 / 3.0 * M_PI * std::pow(st.R - a, 3)).epsilon(1e-12));
    const double half = 0.5 * (st.R - a);
    const double rho = inner[k] / double(counts[k]) / (4.0 / 3.0 * M_PI * half * half * half);
    const double eta = rho * 4.0 / 3.0 * M_PI * a * a * a;
    const double Z_cs = (1 + eta + eta * eta - eta * eta * eta) / std::pow(1 - eta, 3);
    CAPTURE(eta);
    CAPTURE(st.P / (rho * T));
    CAPTURE(Z_cs);
    // 8 %, not the fixed container's 5 % (hard_spheres_test.cpp): after the expansion the gas
    // rings (a radial sound wave), which the inner count samples (measured -5.9 % and +2.6 %).
    CHECK(std::abs(st.P / (rho * T) / Z_cs - 1) < 0.08);
    // The volume itself: N / V against the homogeneous density. The pile-up at the wall puts
    // N / V a few per cent above it, the ringing within a few per cent (measured 1.073 and
    // 0.983); the container's 4/3 pi R^3 puts it 8-13 % below (0.873 and 0.924).
    const double mean_over_homogeneous = double(N) / st.V / rho;
    CAPTURE(mean_over_homogeneous);
    CHECK(mean_over_homogeneous > 0.95);
    CHECK(mean_over_homogeneous < 1.12);
  }
}
