#include "swarm/measure/fit.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace swarm;
using doctest::Approx;

TEST_CASE("an exact power law is recovered with zero residuals") {
  std::vector<double> x, y;
  for (int i = 1; i <= 10; ++i) {
    x.push_back(i * 1.7);
    y.push_back(3.0 * std::pow(i * 1.7, -0.5));
  }
  const PowerLawFit f = fit_power_law(x, y);
  REQUIRE(f.valid);
  CHECK(f.slope == Approx(-0.5).epsilon(1e-12));
  CHECK(f.intercept == Approx(std::log(3.0)).epsilon(1e-12));
  CHECK(f.r_squared == Approx(1.0));
  CHECK(f.slope_stderr < 1e-10);
  for (double r : f.residuals) CHECK(std::abs(r) < 1e-12);
}

TEST_CASE("residuals, R^2 and the slope error of a noisy line, by hand") {
  // ln y = 1 + 2 ln x + e with e = +0.1, -0.1, +0.1, -0.1 at ln x = 0, 1, 2, 3.
  std::vector<double> x, y;
  const double e[] = {0.1, -0.1, 0.1, -0.1};
  for (int i = 0; i < 4; ++i) {
    x.push_back(std::exp(double(i)));
    y.push_back(std::exp(1 + 2 * i + e[i]));
  }
  const PowerLawFit f = fit_power_law(x, y);
  // Least squares by hand: Sxx = 5, Sxy = 10 - 0.2 (from e . (lnx - 1.5) = -0.2).
  CHECK(f.slope == Approx(2 - 0.2 / 5));
  const double ss_res = [&] {
    double s = 0;
    for (double r : f.residuals) s += r * r;
    return s;
  }();
  CHECK(f.slope_stderr == Approx(std::sqrt(ss_res / 2 / 5)));
  CHECK(f.r_squared < 1.0);
  CHECK(f.r_squared > 0.99);
}

TEST_CASE("points with non-positive values are left out, and too few points give no fit") {
  const PowerLawFit f = fit_power_law({1, 2, 3, 4, 5}, {1, 0, 2, -1, 3});
  CHECK(f.used == std::vector<int>{0, 2, 4});
  CHECK(f.valid);
  CHECK_FALSE(fit_power_law({1, 2}, {1, 2}).valid);
  CHECK_FALSE(fit_power_law({2, 2, 2}, {1, 2, 3}).valid);
}
