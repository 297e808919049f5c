// The blocking error against series whose error of the mean is known in closed form: AR(1)
// processes x_t = phi x_(t-1) + e_t, for which n Var(mean) -> Var(x) (1 + phi) / (1 - phi)
// (twice the integrated autocorrelation time, 1 + 2 sum phi^k), and against the spread of
// the means of many independent series.

#include "swarm/measure/blocking.h"

#include <doctest/doctest.h>

#include <cmath>
#include <random>

using namespace swarm;

namespace {

/// A stationary AR(1) series of n values with unit innovations, from its own seed.
std::vector<double> ar1(double phi, std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> e(0.0, 1.0);
  std::vector<double> x(n);
  double v = e(rng) / std::sqrt(1 - phi * phi);  // drawn from the stationary distribution
  for (double& xi : x) xi = v = phi * v + e(rng);
  return x;
}

/// The true standard error of the mean of n values of the AR(1) process (exact, edges too).
double ar1_true_se(double phi, std::size_t n) {
  const double var_x = 1 / (1 - phi * phi);
  double sum = double(n);  // sum over all pairs (s, t) of phi^|s - t|
  double p = 1;
  for (std::size_t k = 1; k < n; ++k) {
    p *= phi;
    sum += 2 * double(n - k) * p;
  }
  return std::sqrt(var_x * sum) / double(n);
}

struct Spread {
  double rms_se = 0;    ///< root mean square of the quoted errors
  double sd_means = 0;  ///< the standard deviation of the series' means
};

Spread over_series(double phi, std::size_t n, int series) {
  double se2 = 0, m1 = 0, m2 = 0;
  for (int k = 0; k < series; ++k) {
    const auto b = blocking_error(ar1(phi, n, 1000 + std::uint64_t(k)));
    REQUIRE(b);
    se2 += b->se * b->se;
    m1 += b->mean;
    m2 += b->mean * b->mean;
  }
  Spread s;
  s.rms_se = std::sqrt(se2 / series);
  m1 /= series;
  s.sd_means = std::sqrt((m2 - series * m1 * m1) / (series - 1));
  return s;
}

}  // namespace

TEST_CASE("blocking: the error of a correlated mean within 15 % of the closed form") {
  const std::size_t n = 1 << 16;
  // Independent, positively correlated (tau_int = 10), strongly so (tau_int = 50), and
  // alternating (phi < 0: neighbours cancel, the error is below sd / sqrt(n)).
  for (double phi : {0.0, 0.9, 0.98, -0.5}) {
    CAPTURE(phi);
    const double truth = ar1_true_se(phi, n);
    const Spread s = over_series(phi, n, 20);
    CAPTURE(truth);
    CAPTURE(s.rms_se);
    CHECK(std::abs(s.rms_se / truth - 1) < 0.15);
  }
  // One series: the factor over the naive error, sqrt((1 + phi) / (1 - phi)) = 4.36 for 0.9.
  const auto b = blocking_error(ar1(0.9, n, 7));
  REQUIRE(b);
  CHECK(b->plateau);
  CHECK(b->se / b->naive_se == doctest::Approx(std::sqrt(19.0)).epsilon(0.15));
  CHECK(b->effective_count == doctest::Approx(double(n) / 19).epsilon(0.3));
  CHECK(b->level > 3);
}

TEST_CASE("blocking: the quoted error matches the spread of independent means") {
  // Not the closed form this time: 200 independent series, each mean's quoted error against
  // the standard deviation of the 200 means (which has its own ~5 % sampling error).
  const Spread s = over_series(0.9, 1 << 12, 200);
  CAPTURE(s.rms_se);
  CAPTURE(s.sd_means);
  CHECK(std::abs(s.rms_se / s.sd_means - 1) < 0.15);
}

TEST_CASE("blocking: short and degenerate series") {
  CHECK_FALSE(blocking_error({1, 2, 3}));
  const auto constant = blocking_error(std::vector<double>(64, 2.5));
  REQUIRE(constant);
  CHECK(constant->mean == 2.5);
  CHECK(constant->se == 0);
  // 5 values: an odd level drops its last value when halved; the mean is over all five.
  const auto five = blocking_error({10, 1, 2, 3, 4});
  REQUIRE(five);
  CHECK(five->mean == 4);
  CHECK(five->used == 5);
}

TEST_CASE("blocking a ratio: a wall temperature's error from its hits' energies") {
  // Interval i: w_i hits (Poisson, mean 20) each carrying an energy whose interval mean
  // follows an AR(1) around 3, the temperature sum(E) / sum(w). Against 200 independent runs.
  const int runs = 200;
  const std::size_t n = 1 << 12;
  double se2 = 0, m1 = 0, m2 = 0;
  for (int r = 0; r < runs; ++r) {
    std::mt19937_64 rng(50 + std::uint64_t(r));
    std::poisson_distribution<int> hits(20);
    const std::vector<double> drift = ar1(0.8, n, 9000 + std::uint64_t(r));
    std::vector<double> energy(n), weight(n);
    for (std::size_t i = 0; i < n; ++i) {
      weight[i] = hits(rng);
      energy[i] = weight[i] * (3 + 0.3 * drift[i]);
    }
    const auto b = blocking_error_of_ratio(energy, weight);
    REQUIRE(b);
    se2 += b->se * b->se;
    m1 += b->mean;
    m2 += b->mean * b->mean;
  }
  m1 /= runs;
  const double sd = std::sqrt((m2 - runs * m1 * m1) / (runs - 1));
  CHECK(m1 == doctest::Approx(3).epsilon(0.01));
  CHECK(std::abs(std::sqrt(se2 / runs) / sd - 1) < 0.15);
  CHECK_FALSE(blocking_error_of_ratio({1, 2, 3, 4}, {0, 0, 0, 0}));
}
