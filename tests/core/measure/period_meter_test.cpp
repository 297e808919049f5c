#include "swarm/measure/period_meter.h"

#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "swarm/methods/integrators.h"
#include "swarm/physics/analytic.h"
#include "test_systems.h"

using namespace swarm;
using doctest::Approx;

namespace {

/// Feeds particle i of the system to a meter every `frame` of time for `duration`, stepping
/// the system with `method` at dt in between (the live app's steps and frames).
PeriodMeter measure_stepped(System s, std::size_t i, Method method, double dt, int steps_per_frame,
                            double duration) {
  PeriodMeter meter(stiffness(s));
  for (double t = 0; t <= duration; t += dt * steps_per_frame) {
    const Vec3 R = cm_position(s), V = cm_velocity(s);
    meter.add(s.t, s.particles[i].r - R, s.particles[i].v - V);
    for (int k = 0; k < steps_per_frame; ++k) step(method, s, dt);
  }
  return meter;
}

}  // namespace

TEST_CASE("the period meter finds 2 pi / sqrt(J M) from the analytic orbits, for any mass and J") {
  // The Fig. 1 masses (0.25 to 1.5) under three couplings, each particle sampled every
  // frame of a 60 Hz display at speed 1 (the exact positions straight from eq. 7).
  for (double J : {0.05, 1.0, 7.0}) {
    const System s = testing::four_masses(J);
    const AnalyticSolution exact(s);
    const double formula = 2 * M_PI / std::sqrt(J * total_mass(s));
    const double frame = std::min(1.0 / 60, formula / 8);  // at least 8 samples per period
    for (std::size_t i = 0; i < s.particles.size(); ++i) {
      PeriodMeter meter(stiffness(s));
      for (double t = 0; t < 3 * formula; t += frame) {
        const Particle p = exact.particle_at(i, t);
        meter.add(t, p.r - exact.cm_position_at(t), p.v - exact.cm_velocity());
      }
      CAPTURE(J);
      CAPTURE(i);
      REQUIRE(meter.status() == PeriodStatus::measured);
      CHECK(meter.periods_measured() >= 2);
      CHECK(*meter.period() == Approx(formula).epsilon(0.005));
      CHECK(std::abs(*meter.relative_difference()) < 0.005);
      CHECK(*meter.formula_period() == Approx(formula));
    }
  }
}

TEST_CASE("the period meter counts the periods that passed, not its crossings") {
  // x = cos(omega t + phase) sampled 20 times a period for a duration of D periods: the
  // crossings in one direction are a period apart, so the whole periods between the first
  // and the last of them are floor(D) or floor(D) - 1 (the first crossing comes within one
  // period of the start), whatever the phase; never the about 2 D that counting every pair
  // of either direction gives (21 at t = 51 for a period of 4.44, issue 39).
  const double omega = 1.415, period = 2 * M_PI / omega;
  for (double periods : {1.3, 3.0, 11.5, 40.25})
    for (double phase : {0.0, 0.7, 1.9, 3.3, 5.1}) {
      PeriodMeter meter(omega * omega);
      const double h = period / 20;
      for (double t = 0; t <= periods * period; t += h)
        meter.add(t, Vec3(std::cos(omega * t + phase), 0, 0), Vec3(-omega * std::sin(omega * t + phase), 0, 0));
      CAPTURE(periods);
      CAPTURE(phase);
      const int whole = int(std::floor(periods));
      CHECK(meter.periods_measured() <= whole);
      CHECK(meter.periods_measured() >= whole - 1);
      if (whole >= 2) CHECK(*meter.period() == Approx(period).epsilon(1e-4));
    }
}

TEST_CASE("the period meter is accurate with few samples per period (Hermite interpolation)") {
  // One oscillator x = cos(omega t) + 0.3 sin(omega t) sampled n times per period, with a
  // phase offset so that no sample falls on a crossing. The error bound in period_meter.h is
  // (2 pi / n)^4 / (192 pi).
  const double omega = 1.7, period = 2 * M_PI / omega;
  for (int n : {6, 12, 60}) {
    PeriodMeter meter(omega * omega);
    const double h = period / n;
    for (double t = 0.123 * h; t < 4 * period; t += h)
      meter.add(t, Vec3(std::cos(omega * t) + 0.3 * std::sin(omega * t), 0, 0),
                Vec3(omega * (-std::sin(omega * t) + 0.3 * std::cos(omega * t)), 0, 0));
    const double bound = std::pow(2 * M_PI / n, 4) / (192 * M_PI);
    CAPTURE(n);
    REQUIRE(meter.period().has_value());
    CHECK(std::abs(*meter.period() - period) / period <= bound);
  }
}

TEST_CASE("the period meter on numerical methods at a display's frame sampling") {
  // The Fig. 1 preset's step (dt = 0.005) with 4 steps per frame, as the live app feeds it.
  // Euler-Cromer and RK4 keep the period to O((omega dt)^2); the measured one must stay
  // within 0.5% of the formula.
  for (Method m : {Method::euler_cromer, Method::rk4, Method::verlet}) {
    for (double J : {0.2, 1.0}) {
      const System s = testing::four_masses(J);
      const double formula = 2 * M_PI / std::sqrt(J * total_mass(s));
      for (std::size_t i : {std::size_t(0), std::size_t(3)}) {
        const PeriodMeter meter = measure_stepped(s, i, m, 0.005, 4, 3 * formula);
        CAPTURE(J);
        CAPTURE(i);
        REQUIRE(meter.status() == PeriodStatus::measured);
        CHECK(std::abs(*meter.period() - formula) / formula < 0.005);
      }
    }
  }
}

TEST_CASE("the period meter: measuring, no period for J <= 0, a particle at the centre") {
  const System s = testing::four_masses(1.0);
  const AnalyticSolution exact(s);
  PeriodMeter meter(stiffness(s));
  CHECK(meter.status() == PeriodStatus::measuring);
  // A quarter of a period: no crossing pair yet.
  const double T = exact.period();
  for (double t = 0; t < 0.25 * T; t += T / 100) {
    const Particle p = exact.particle_at(1, t);
    meter.add(t, p.r - exact.cm_position_at(t), p.v - exact.cm_velocity());
  }
  CHECK(meter.status() == PeriodStatus::measuring);
  CHECK(!meter.period().has_value());
  CHECK(!meter.relative_difference().has_value());

  PeriodMeter repulsive(-2.0);
  repulsive.add(0, Vec3(1, 0, 0), Vec3(0, 1, 0));
  CHECK(repulsive.status() == PeriodStatus::no_period);
  CHECK(!repulsive.formula_period().has_value());
  CHECK(PeriodMeter(0.0).status() == PeriodStatus::no_period);

  PeriodMeter still(1.0);
  still.add(0, Vec3::Zero(), Vec3::Zero());
  CHECK(still.status() == PeriodStatus::at_centre);
}

TEST_CASE("the period meter does not time across a gap longer than a quarter period") {
  const double omega = 1.0, period = 2 * M_PI;
  PeriodMeter meter(omega * omega);
  auto feed = [&](double t) {
    meter.add(t, Vec3(std::cos(t), std::sin(t), 0), Vec3(-std::sin(t), std::cos(t), 0));
  };
  for (double t = 0; t < 0.9 * period; t += 0.05) feed(t);
  // A jump of 2.3 periods (fast-forward): the crossings before it are forgotten.
  for (double t = 3.2 * period; t < 4.7 * period; t += 0.05) feed(t);
  CHECK(meter.gaps() == 1);
  REQUIRE(meter.period().has_value());
  CHECK(*meter.period() == Approx(period).epsilon(1e-6));
}
