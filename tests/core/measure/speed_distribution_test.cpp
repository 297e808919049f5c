// The Maxwell distribution and the goodness-of-fit measures against it.

#include "swarm/measure/speed_distribution.h"

#include <doctest/doctest.h>

#include <cmath>

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
}
