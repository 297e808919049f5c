#include "swarm/measure/virial_balance.h"

#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "swarm/measure/wall_time_average.h"
#include "swarm/run/run.h"
#include "test_systems.h"

using namespace swarm;
using doctest::Approx;

namespace {

RunPlan container_plan(double dt, long steps, long sample_every) {
  RunPlan plan;
  plan.engine = {Method::analytic, CollisionMode::paper, 1.0};
  plan.dt = dt;
  plan.steps = steps;
  plan.sample_every = sample_every;
  return plan;
}

// The sums over the particles, written out here rather than taken from diagnostics.
double G_by_hand(const System& s) {
  double G = 0;
  for (const Particle& p : s.particles)
    G += p.m * (p.r.x() * p.v.x() + p.r.y() * p.v.y() + p.r.z() * p.v.z());
  return G;
}

double kinetic_by_hand(const System& s) {
  double KE = 0;
  for (const Particle& p : s.particles) KE += 0.5 * p.m * p.v.squaredNorm();
  return KE;
}

/// U = (J M / 2) sum m |r - R_cm|^2, the springs' energy (eq. 13).
double springs_by_hand(const System& s) {
  double M = 0;
  Vec3 moment = Vec3::Zero();
  for (const Particle& p : s.particles) M += p.m, moment += p.m * p.r;
  const Vec3 R = moment / M;
  double sum = 0;
  for (const Particle& p : s.particles) sum += p.m * (p.r - R).squaredNorm();
  return 0.5 * s.J * M * sum;
}

}  // namespace

TEST_CASE("virial balance: a window's means, G at its ends, and a relaxing G flagged") {
  // 400 intervals of 0.01: G fluctuates about 0 (independent draws of spread 1 at the
  // samples, as in equilibrium), and for the relaxing one also carries a memory
  // 20 exp(-t / 0.1) of its start; 2KE - 2U = 10, and 3PV follows the identity
  // dG/dt = (2KE - 2U) - 3PV.
  std::mt19937_64 rng(3);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<VirialInterval> balanced, relaxing;
  double G = noise(rng), memory = 20;
  for (int i = 0; i < 400; ++i) {
    const double t = 0.01 * (i + 1), next = noise(rng), next_memory = 20 * std::exp(-t / 0.1);
    balanced.push_back({t, 0.01, 10 - (next - G) / 0.01, 10, G, next});
    relaxing.push_back({t, 0.01, 10 - (next + next_memory - G - memory) / 0.01, 10, G + memory,
                        next + next_memory});
    G = next, memory = next_memory;
  }
  const auto b = virial_balance(balanced, 1.0);
  REQUIRE(b);
  CHECK(b->start == Approx(1.0));
  CHECK(b->intervals == 300);
  CHECK(b->G_start == Approx(balanced[100].G_start));
  CHECK(b->G_end == Approx(G));
  CHECK(b->kinetic == Approx(10.0));
  CHECK(b->imbalance == Approx(b->wall - 10.0));
  CHECK(std::abs(b->residual) < 1e-12);
  // sqrt(2 <G^2>) / 3 with <G^2> = 1: G's mean square over the window (trapezoid) by hand.
  double G_squared = 0;
  for (std::size_t i = 100; i < 400; ++i)
    G_squared += 0.5 * (balanced[i].G_start * balanced[i].G_start +
                        balanced[i].G_end * balanced[i].G_end) * 0.01;
  CHECK(b->error == Approx(std::sqrt(2 * G_squared / 3) / 3).epsilon(1e-9));
  CHECK(b->error == Approx(std::sqrt(2.0) / 3).epsilon(0.15));
  CHECK(b->holds);
  // From t = 1 the memory is 20 exp(-10) = 1e-3: the window balances. From t = 0.1 it is
  // 7.4, against G's spread of 1: off by 7.4 / 3.9 = 1.9, four errors (the memory raises G's
  // mean square over the window to 1 + 7.4^2 0.1 / 2 / 3.9 = 1.7, so the error is
  // sqrt(2 1.7) / 3.9 = 0.47); blocking 3PV - (2KE - 2U) would give 1.1 (measured).
  const auto late = virial_balance(relaxing, 1.0);
  REQUIRE(late);
  CHECK(late->holds);
  const auto d = virial_balance(relaxing, 0.1);
  REQUIRE(d);
  MESSAGE("relaxing from 0.1: imbalance " << d->imbalance << " +- " << d->error);
  CHECK_FALSE(d->holds);
  CHECK(d->imbalance == Approx((relaxing[10].G_start - G - memory) / 3.9).epsilon(1e-9));
  CHECK_FALSE(virial_balance(balanced, 3.95));  // 5 intervals: no balance
}

TEST_CASE("virial balance, J = 0: dG = 2 KE dt + r.dp at the wall, and a long run balances") {
  // 400 particles (masses 4-5) started within 0.9 R, speeds up to 1.5, R = 1; 20 time units.
  System s = testing::random_swarm(400, 0.0, 11, 0.9, 1.5);
  const RunPlan plan = container_plan(1e-3, 20000, 20);
  // By hand: each hit's impulse dp = m (v1 - v0) and where the paper's scheme gives it, at
  // the step's starting position r0 (free flight: v changes only at the wall).
  auto engine = make_engine(s, plan.engine);
  double impulse = 0, wall_virial = 0;  // sum |dp|, sum r0.dp
  for (long k = 0; k < plan.steps; ++k) {
    const System before = engine->system();
    engine->step(plan.dt);
    const System& after = engine->system();
    for (std::size_t i = 0; i < before.particles.size(); ++i) {
      const Particle& p = before.particles[i];
      const Vec3 dp = p.m * (after.particles[i].v - p.v);
      impulse += dp.norm();
      wall_virial += p.r.dot(dp);
    }
  }
  const double T = 20, KE = kinetic_by_hand(s);
  const double G0 = G_by_hand(s), G1 = G_by_hand(engine->system());
  // The identity itself, step by step: G1 - G0 = 2 KE T + sum r0.dp.
  CHECK(G1 - G0 == Approx(2 * KE * T + wall_virial).epsilon(1e-9));

  Run run(s, plan);
  run.finish();
  const auto& samples = run.samples();
  CHECK(samples.front().G == Approx(G0).epsilon(1e-12));
  CHECK(samples.back().G == Approx(G1).epsilon(1e-12));
  const auto b = virial_balance(virial_intervals(samples), 0.0);
  REQUIRE(b);
  CHECK(b->wall == Approx(1.0 * impulse / T).epsilon(1e-9));  // 3 P V = R sum |dp| / T
  CHECK(b->kinetic == Approx(2 * KE).epsilon(1e-12));
  CHECK(b->G_start == Approx(G0).epsilon(1e-12));
  CHECK(b->G_end == Approx(G1).epsilon(1e-12));
  // The scheme's offset: 3 P V takes every impulse at R, the wall's virial at |r0| <= R.
  const double offset = (1.0 * impulse + wall_virial) / T;
  MESSAGE("3PV = " << b->wall << ", 2KE = " << b->kinetic << ", the scheme's offset "
                   << offset / b->wall << " of 3PV, imbalance " << b->imbalance << " +- "
                   << b->error);
  CHECK(offset > 0);
  CHECK(offset < 1e-3 * b->wall);
  CHECK(offset < 0.5 * b->error);  // 0.28 of it: the flag cannot mistake it for a memory
  CHECK(b->imbalance == Approx(-(G1 - G0) / T).epsilon(1e-12));
  CHECK(b->residual == Approx(offset).epsilon(1e-6));
  CHECK(b->holds);
  const WallTimeAverages a = wall_time_averages(wall_intervals(samples), virial_intervals(samples));
  REQUIRE(a.virial);
  CHECK(a.virial->holds);
  CHECK(a.virial->start == Approx(a.start));
}

TEST_CASE("virial balance, J > 0 and J < 0: the terms against the particles, and long runs balance") {
  for (const double sign : {1.0, -1.0}) {
    CAPTURE(sign);
    // sqrt(|J| M) = 1, amplitudes beyond the unit container: the wall is hit often.
    const System s = testing::crowded_swarm(300, sign, 5);
    const RunPlan plan = container_plan(1e-3, 20000, 5);
    auto engine = make_engine(s, plan.engine);
    double impulse = 0, kinetic = 0;  // sum |dp_r|; the integral of 2KE - 2U (trapezoid per step)
    double before = 2 * kinetic_by_hand(s) - 2 * springs_by_hand(s);
    for (long k = 0; k < plan.steps; ++k) {
      impulse += engine->step(plan.dt).radial_impulse;
      const System& now = engine->system();
      const double after = 2 * kinetic_by_hand(now) - 2 * springs_by_hand(now);
      kinetic += 0.5 * (before + after) * plan.dt;
      before = after;
    }
    const double T = 20;
    Run run(s, plan);
    run.finish();
    const System& end = run.engine().system();
    const Sample& last = run.samples().back();
    CHECK(last.G == Approx(G_by_hand(end)).epsilon(1e-12));
    CHECK(last.KE == Approx(kinetic_by_hand(end)).epsilon(1e-12));
    CHECK(last.PE == Approx(springs_by_hand(end)).epsilon(1e-9));
    const auto b = virial_balance(virial_intervals(run.samples()), 0.0);
    REQUIRE(b);
    CHECK(b->wall == Approx(1.0 * impulse / T).epsilon(1e-9));
    CHECK(b->kinetic == Approx(kinetic / T).epsilon(1e-4));
    CHECK(b->G_end == Approx(G_by_hand(end)).epsilon(1e-12));
    // The identity: mean(3PV) - mean(2KE - 2U) = -(G1 - G0) / T, but for the residual: the
    // scheme's offset (impulses booked at R, given at r0; J = 0 above: 1e-4 of 3PV) and the
    // trapezoid's.
    CHECK(b->imbalance == Approx(-(b->G_end - b->G_start) / T).epsilon(1e-12));
    MESSAGE("3PV = " << b->wall << ", 2KE - 2U = " << b->kinetic << ", imbalance "
                     << b->imbalance << " +- " << b->error << ", residual " << b->residual);
    CHECK(std::abs(b->residual) < 1e-3 * std::abs(b->wall));
    CHECK(b->holds);
    const WallTimeAverages a =
        wall_time_averages(wall_intervals(run.samples()), virial_intervals(run.samples()));
    REQUIRE(a.virial);
    CHECK(a.virial->holds);
  }
}

TEST_CASE("virial balance: a gas still flowing out to the wall; G's memory is P's error") {
  // The held-out case in small: J = 0, particles started uniformly within 0.9 R with
  // velocities uniform in a ball of radius 1, R = 1, dt = 0.0005, 1 time unit: the first waves
  // to the wall dominate the window.
  System s = testing::random_swarm(1500, 0.0, 21, 0.9, 1.0);
  const RunPlan plan = container_plan(5e-4, 2000, 10);
  Run run(s, plan);
  run.finish();
  const auto& samples = run.samples();
  const WallTimeAverages a = wall_time_averages(wall_intervals(samples), virial_intervals(samples));
  REQUIRE(a.virial);
  REQUIRE(a.P);
  // The exact equilibrium value from the run's own KE (kept: J = 0, a still wall): 3 P V = 2 KE.
  const double V = sphere_volume(1.0), P_exact = 2 * kinetic_by_hand(s) / (3 * V);
  MESSAGE("P = " << a.P->mean << " +- " << a.P->se << " from t = " << a.start << ", exact "
                 << P_exact << "; imbalance " << a.virial->relative() << " of 3PV +- "
                 << a.virial->error / a.virial->wall << ", holds " << a.virial->holds);
  // Flagged, or an interval that holds the exact value.
  CHECK((!a.virial->holds || std::abs(a.P->mean - P_exact) <= 2 * a.P->se));
  // The window's P misses the equilibrium by G's memory (and the scheme's residual) exactly.
  CHECK(3 * V * (a.P->mean - P_exact) ==
        Approx(a.virial->imbalance + a.virial->residual).epsilon(1e-9));
  CHECK(std::abs(a.virial->relative()) > 0.05);
}

TEST_CASE("virial balance: the held-out gas's early windows flagged on their own, each run's P honest") {
  // The held-out case: J = 0, 1,500 particles started uniformly within 0.9 R with
  // velocities uniform in a ball, R = 1, dt = 0.0005, 4 time units, sampled every 4 steps as
  // an ensemble samples it; 8 seeds. A window from 0.2 or 0.4 starts while the gas that flowed
  // out to the wall is still breathing (G's rms over the window 2-4x its spread at the end):
  // measured, 13 of 16 such windows flagged (the old blocking error, 3x wider: 1 of 16). The
  // start wall_time_averages picks must then balance, or P's interval must hold 2 KE / 3V.
  // Fewer particles would not do: the breathing grows as N, G's spread as sqrt(N) (300: 7 of 16).
  int flagged = 0, honest = 0;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    const System s = testing::random_swarm(1500, 0.0, seed, 0.9, 1.0);
    Run run(s, container_plan(5e-4, 8000, 4));
    run.finish();
    const auto virial = virial_intervals(run.samples());
    for (const double from : {0.2, 0.4}) {
      const auto b = virial_balance(virial, from);
      REQUIRE(b);
      flagged += !b->holds;
    }
    const WallTimeAverages a = wall_time_averages(wall_intervals(run.samples()), virial);
    REQUIRE(a.virial);
    REQUIRE(a.P);
    const double P_exact = 2 * kinetic_by_hand(s) / (3 * sphere_volume(1.0));
    honest += !a.virial->holds || std::abs(a.P->mean - P_exact) <= 1.96 * a.P->se;
  }
  MESSAGE(flagged << " of 16 windows from 0.2 and 0.4 flagged; " << honest << " of 8 runs honest");
  CHECK(flagged >= 11);
  CHECK(honest == 8);
}

TEST_CASE("virial balance: long equilibrated runs are not flagged beyond the 2 errors' rate") {
  // 8 seeds each of J = 0 (200 particles within 0.9 R, speeds in a ball, 40 time units) and
  // J = +-1 / M (the crowded swarms above, 20 time units), dt = 0.001. A window from the middle
  // of an equilibrated run is flagged at the rate of |z| > 2, about 5 %: at most 4 of the 24
  // (more happens 0.6 % of the time at a true 5 %, 9 % at 10 %). Measured: 0, 0 and 0 of 8;
  // over 60 seeds each, J = 1: 5 of 60, rms z 1.08; J = -1: 3, rms 0.98; J = 0: 7, rms 1.14,
  // the breathing of a gas in a sphere, which only dephases, not quite gone at t = 20. The
  // start wall_time_averages picks, of eleven, balances in every run (180 of 180).
  int middle_flagged = 0;
  for (const double J : {0.0, 1.0, -1.0}) {
    CAPTURE(J);
    int flagged = 0, runs_flagged = 0;
    for (std::uint64_t seed = 1; seed <= 8; ++seed) {
      const System s = J == 0 ? testing::random_swarm(200, 0.0, seed, 0.9, 1.0)
                              : testing::crowded_swarm(200, J, seed);
      const double duration = J == 0 ? 40 : 20;
      Run run(s, container_plan(1e-3, long(duration * 1000), long(duration / 2)));
      run.finish();
      const auto virial = virial_intervals(run.samples());
      const auto b = virial_balance(virial, duration / 2);
      REQUIRE(b);
      flagged += !b->holds;
      const WallTimeAverages a = wall_time_averages(wall_intervals(run.samples()), virial);
      REQUIRE(a.virial);
      runs_flagged += !a.virial->holds;
    }
    middle_flagged += flagged;
    MESSAGE("J = " << J << ": " << flagged << " of 8 windows from the middle flagged, "
                   << runs_flagged << " of 8 runs");
    CHECK(runs_flagged == 0);
  }
  CHECK(middle_flagged <= 4);
}
