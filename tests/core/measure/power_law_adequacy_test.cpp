#include "swarm/measure/power_law_adequacy.h"

#include <doctest/doctest.h>

#include <cmath>
#include <vector>

using namespace swarm;
using doctest::Approx;

TEST_CASE("a power law with a curve in its residuals is judged systematic, scatter is not") {
  // ln y = 2 ln x + 0.3 (ln x - 1.5)^2: a parabola the line cannot follow. Residuals from the
  // line fit are a parabola in ln x too, so neighbours share their sign.
  std::vector<double> x, y, scatter_y;
  const double noise[] = {0.05, -0.04, 0.06, -0.05, 0.03, -0.06, 0.05, -0.03, 0.04, -0.05};
  for (int i = 0; i < 10; ++i) {
    const double lx = 3.0 * i / 9;
    x.push_back(std::exp(lx));
    y.push_back(std::exp(2 * lx + 0.3 * (lx - 1.5) * (lx - 1.5)));
    scatter_y.push_back(std::exp(2 * lx + noise[i]));
  }
  const PowerLawFit curved = fit_power_law(x, y);
  REQUIRE(curved.valid);
  // Durbin-Watson by hand from the residuals the fit reports.
  double num = 0, den = 0;
  for (std::size_t i = 0; i < curved.residuals.size(); ++i) {
    den += curved.residuals[i] * curved.residuals[i];
    if (i > 0)
      num += (curved.residuals[i] - curved.residuals[i - 1]) *
             (curved.residuals[i] - curved.residuals[i - 1]);
  }
  const PowerLawAdequacy a = judge_power_law(curved);
  CHECK(a.durbin_watson == Approx(num / den));
  CHECK(curved.r_squared > 0.9);  // a convincing-looking line...
  CHECK(a.systematic);            // ...that the residuals refute
  CHECK(a.poor());

  // Alternating noise about an exact law: residuals change sign every point, DW near 4.
  const PowerLawAdequacy b = judge_power_law(fit_power_law(x, scatter_y));
  CHECK(b.durbin_watson > 3);
  CHECK_FALSE(b.poor());

  // An exact law: zero residuals, nothing to warn of.
  std::vector<double> exact;
  for (double xi : x) exact.push_back(5 * std::pow(xi, -1.5));
  CHECK_FALSE(judge_power_law(fit_power_law(x, exact)).poor());
  // Too few points to see a pattern: the curve is not called systematic with five.
  const std::vector<double> x5(x.begin(), x.begin() + 5), y5(y.begin(), y.begin() + 5);
  CHECK_FALSE(judge_power_law(fit_power_law(x5, y5)).systematic);
}

TEST_CASE("points that follow no line are judged scattered") {
  const std::vector<double> x = {1, 2, 3, 4, 5, 6, 7, 8};
  const std::vector<double> y = {5, 1, 4, 2, 6, 1, 5, 2};
  const PowerLawFit f = fit_power_law(x, y);
  REQUIRE(f.valid);
  CHECK(f.r_squared < 0.9);
  CHECK(judge_power_law(f).scattered);
}
