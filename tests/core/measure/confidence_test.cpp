// Intervals against tables and against their promise: the share of intervals that hold the
// true value, over many simulated data sets whose truth is known.

#include "swarm/measure/confidence.h"

#include <doctest/doctest.h>

#include <cmath>
#include <random>

using namespace swarm;
using doctest::Approx;

TEST_CASE("normal and Student-t quantiles match the printed tables") {
  CHECK(normal_quantile(0.975) == Approx(1.959964).epsilon(1e-6));
  CHECK(normal_cdf(-1.0) == Approx(0.158655).epsilon(1e-5));
  // Student's t, two-sided 95 % (Abramowitz and Stegun, table 26.10).
  CHECK(student_t_quantile(0.975, 1) == Approx(12.706205).epsilon(1e-6));
  CHECK(student_t_quantile(0.975, 2) == Approx(4.303).epsilon(1e-4));
  CHECK(student_t_quantile(0.975, 5) == Approx(2.570582).epsilon(1e-6));
  CHECK(student_t_quantile(0.975, 31) == Approx(2.040).epsilon(1e-3));
  CHECK(student_t_quantile(0.995, 10) == Approx(3.169).epsilon(1e-4));
  CHECK(student_t_quantile(0.025, 5) == Approx(-2.570582).epsilon(1e-6));
  CHECK(student_t_quantile(0.975, 1e6) == Approx(1.96).epsilon(1e-3));
  CHECK(student_t_cdf(0, 3) == Approx(0.5));
}

TEST_CASE("mean interval: the formula, and 95 % coverage over 4,000 small samples") {
  const MeanInterval m = mean_interval({1, 2, 3, 4});
  CHECK(m.mean == 2.5);
  CHECK(m.sd == Approx(std::sqrt(5.0 / 3.0)));
  CHECK(m.se == Approx(m.sd / 2));
  REQUIRE(m.lo);
  CHECK(*m.hi - m.mean == Approx(3.182446 * m.se).epsilon(1e-5));
  CHECK_FALSE(mean_interval({7}).lo);
  std::mt19937_64 rng(3);
  std::normal_distribution<double> x(10.0, 2.0);
  int held = 0;
  const int sets = 4000;
  for (int k = 0; k < sets; ++k) {
    std::vector<double> v(5);
    for (double& vi : v) vi = x(rng);
    const MeanInterval i = mean_interval(v);
    held += *i.lo <= 10 && 10 <= *i.hi;
  }
  // 95 % of 4,000: the binomial's sd is 0.34 %.
  CHECK(double(held) / sets == Approx(0.95).epsilon(0.012));
}

TEST_CASE("runs for a half-width: the smallest n whose t interval is narrow enough") {
  const long n = runs_for_half_width(2.0, 0.5);
  // 1.96 * 2 / 0.5 = 7.84 -> n about 62 by the normal; the t quantile makes it 64.
  CHECK(student_t_quantile(0.975, double(n - 1)) * 2 / std::sqrt(double(n)) <= 0.5);
  CHECK(student_t_quantile(0.975, double(n - 2)) * 2 / std::sqrt(double(n - 1)) > 0.5);
  CHECK(n > 60);
  CHECK(n < 70);
  CHECK(runs_for_half_width(0, 0.1) == 0);
  CHECK(runs_for_half_width(1, 0) == -1);
}

TEST_CASE("BCa bootstrap: close to the t interval for a mean, and 95 % coverage when skewed") {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<double> v(40);
  for (double& vi : v) vi = normal(rng);
  auto mean_of = [&v](const std::vector<std::size_t>& runs) {
    double s = 0;
    for (std::size_t r : runs) s += v[r];
    return s / double(runs.size());
  };
  const auto b = bca_interval(v.size(), mean_of);
  REQUIRE(b);
  const MeanInterval t = mean_interval(v);
  CHECK(b->estimate == Approx(t.mean));
  CHECK((b->hi - b->lo) / (*t.hi - *t.lo) == Approx(1).epsilon(0.1));
  // The same seed gives the same interval; another seed a slightly different one.
  CHECK(bca_interval(v.size(), mean_of)->lo == b->lo);

  // A non-linear statistic of skewed data: the log of the mean of exponential values (the
  // truth is log 1 = 0). 400 data sets of 30 values: the BCa interval holds 0 in about 95 %.
  std::exponential_distribution<double> expo(1.0);
  int held = 0, sets = 400;
  for (int k = 0; k < sets; ++k) {
    for (std::size_t i = 0; i < 30; ++i) v[i] = expo(rng);
    v.resize(30);
    auto log_mean = [&v](const std::vector<std::size_t>& runs) {
      double s = 0;
      for (std::size_t r : runs) s += v[r];
      return std::log(s / double(runs.size()));
    };
    const auto i = bca_interval(30, log_mean, 0.95, 1000, std::uint64_t(k));
    REQUIRE(i);
    held += i->lo <= 0 && 0 <= i->hi;
  }
  // The binomial's sd over 400 sets is 1.1 %: 91-99 % is more than three of them.
  CHECK(double(held) / sets > 0.91);
  CHECK(double(held) / sets < 0.99);
  CHECK_FALSE(bca_interval(2, mean_of));
}
