// The Maxwell distribution and the goodness-of-fit measures against it.

#include "swarm/measure/speed_distribution.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>

#include "swarm/preset/initial_conditions.h"

using namespace swarm;

TEST_CASE("maxwell_density integrates to maxwell_probability_below, and to 1") {
  double integral = 0;
  const double h = 1e-4;
  for (double x = 0.5 * h; x < 3; x += h) integral += maxwell_density(x) * h;
  CHECK(integral == doctest::Approx(maxwell_probability_below(3)).epsilon(1e-6));
  CHECK(maxwell_probability_below(12) == doctest::Approx(1.0).epsilon(1e-12));
  // The mean of x^2 is 3 (equipartition: each of three components has variance 1).
  double second = 0;
  for (double x = 0.5 * h; x < 12; x += h) second += x * x * maxwell_density(x) * h;
  CHECK(second == doctest::Approx(3.0).epsilon(1e-6));
}

TEST_CASE("a Maxwellian swarm passes the KS test, a uniform-ball one does not") {
  SwarmSpec spec;
  spec.count = 5000;
  spec.mass_min = 1, spec.mass_max = 3;  // mixed masses: each speed scaled by sqrt(m / T)
  spec.velocities = SwarmSpec::Velocities::maxwell;
  spec.temperature = 0.7;
  spec.seed = 3;
  const System hot = generate_swarm(spec);
  const SpeedCheck c = check_speeds(hot);
  CHECK(c.T == doctest::Approx(0.7).epsilon(0.03));
  CHECK(std::sqrt(double(c.n)) * c.ks_distance < 1.63);
  double area = 0;
  for (double d : c.histogram.density) area += d * c.histogram.x_max / 40;
  CHECK(area == doctest::Approx(maxwell_probability_below(4)).epsilon(0.01));

  spec.velocities = SwarmSpec::Velocities::ball;
  const System ball = generate_swarm(spec);
  const SpeedCheck u = check_speeds(ball);
  CHECK(std::sqrt(double(u.n)) * u.ks_distance > 5);
  CHECK(c.maxwellian_p > 0.01);
  CHECK(u.maxwellian_p < 1e-9);
}

TEST_CASE("kolmogorov_tail: the Kolmogorov distribution's tabulated quantiles") {
  // Smirnov's table (Massey 1951, n -> infinity): 1.22 at 10 %, 1.36 at 5 %, 1.63 at 1 %.
  CHECK(kolmogorov_tail(1.2238) == doctest::Approx(0.10).epsilon(0.002));
  CHECK(kolmogorov_tail(1.3581) == doctest::Approx(0.05).epsilon(0.002));
  CHECK(kolmogorov_tail(1.6276) == doctest::Approx(0.01).epsilon(0.002));
  CHECK(kolmogorov_tail(0.1) == 1);
  CHECK(kolmogorov_tail(0.5) == doctest::Approx(0.9639).epsilon(1e-3));  // 1 - K(0.5) = 0.96394
}

TEST_CASE("ks_p_value: a Maxwellian gas at a known T is refused at 5 % in 5 % of samples") {
  // 400 independent gases of 200 particles at T = 1; the speeds scaled by the true T, so
  // that the test is the plain one-sample KS test, whose p is uniform. Binomial(400, 0.05):
  // 20 +- 4.4 refusals; the band is 3.5 standard deviations.
  int refused = 0, refused_estimated = 0;
  for (std::uint64_t seed = 1; seed <= 400; ++seed) {
    SwarmSpec spec;
    spec.count = 200;
    spec.velocities = SwarmSpec::Velocities::maxwell;
    spec.temperature = 1.0;
    spec.cm_at_rest = false;
    spec.seed = seed;
    const System gas = generate_swarm(spec);
    refused += ks_p_value(maxwell_ks_distance(scaled_speeds(gas, 1.0)), 200) < 0.05;
    refused_estimated += check_speeds(gas).maxwellian_p < 0.05;
  }
  CAPTURE(refused);
  CAPTURE(refused_estimated);
  CHECK(refused >= 5);
  CHECK(refused <= 36);
  // With T estimated from the same speeds the test is conservative: fewer refusals.
  CHECK(refused_estimated <= refused);
}
