#include "swarm/physics/regime.h"

#include <doctest/doctest.h>

#include <cmath>
#include <initializer_list>

#include "oscillator_rk4.h"

using namespace swarm;
using doctest::Approx;
using testing::integrate_oscillator;

TEST_CASE("the sign of k = J M alone decides oscillation, free flight or runaway") {
  for (double k : {1e-300, 0.3, 1.0, 4e6}) CHECK(regime_of(k) == Regime::attractive);
  for (double k : {-1e-300, -0.3, -1.0, -4e6}) CHECK(regime_of(k) == Regime::repulsive);
  CHECK(regime_of(0.0) == Regime::free);
  CHECK(regime_of(-0.0) == Regime::free);
}

TEST_CASE("omega_of is the rate sqrt|k| of both the oscillation and the runaway") {
  CHECK(omega_of(0.0) == 0.0);
  CHECK(omega_of(4.0) == 2.0);
  CHECK(omega_of(-9.0) == 3.0);
  for (double k : {1e-12, 0.37, 2.5, 1e8}) {
    CHECK(omega_of(k) * omega_of(k) == Approx(k).epsilon(1e-15));
    CHECK(omega_of(-k) == omega_of(k));
  }
  // Repulsive: x = exp(Omega t) solves x'' = -k x, so after a time t an integrated x grows by
  // exp(omega_of(k) t).
  const double k = -0.8, t = 2.0;
  double x = 1, v = omega_of(k);
  integrate_oscillator(k, t, 20000, x, v);
  CHECK(x == Approx(std::exp(omega_of(k) * t)).epsilon(1e-11));
  CHECK(v == Approx(omega_of(k) * std::exp(omega_of(k) * t)).epsilon(1e-11));
}

TEST_CASE("after period_of(k) an oscillator is back where it started, half-way it is opposite") {
  for (double k : {0.05, 1.0, 3.25, 400.0}) {
    const double T = period_of(k);
    CAPTURE(k);
    const double x0 = 0.7, v0 = -0.4;
    double x = x0, v = v0;
    integrate_oscillator(k, T / 2, 20000, x, v);
    CHECK(x == Approx(-x0).epsilon(1e-10));
    CHECK(v == Approx(-v0).epsilon(1e-10));
    integrate_oscillator(k, T / 2, 20000, x, v);
    CHECK(x == Approx(x0).epsilon(1e-10));
    CHECK(v == Approx(v0).epsilon(1e-10));
    // A quarter period turns a pure displacement into a pure velocity of size omega x0.
    double xq = x0, vq = 0;
    integrate_oscillator(k, T / 4, 20000, xq, vq);
    CHECK(std::abs(xq) < 1e-10 * x0);
    CHECK(vq == Approx(-omega_of(k) * x0).epsilon(1e-10));
  }
}

TEST_CASE("free flight and runaway never come back: their period is infinite") {
  CHECK(std::isinf(period_of(0.0)));
  CHECK(std::isinf(period_of(-1.0)));
  CHECK(std::isinf(period_of(-1e-300)));
  CHECK(period_of(1.0) > 0);
}

TEST_CASE("natural_time_of is 2 pi / sqrt|k|: the period when attractive, as long when repulsive") {
  // k = 4: omega = 2, the period is pi; k = -4: Omega = 2, and in pi the runaway exp(Omega t)
  // grows by e^(2 pi).
  CHECK(natural_time_of(4.0) == doctest::Approx(M_PI));
  CHECK(natural_time_of(4.0) == period_of(4.0));
  CHECK(natural_time_of(-4.0) == doctest::Approx(M_PI));
  CHECK(std::isinf(natural_time_of(0.0)));
}
