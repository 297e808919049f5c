// The scheduler's cheap arctangent and logarithm against the C library, over their whole range:
// the windows are widened by the stated bounds, so the bounds must hold.
#include "math/fast_math.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>

TEST_CASE("fast_atan2 stays within kAtanError of atan2 in every quadrant") {
  double worst = 0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const double angle = -M_PI + 2 * M_PI * (i + 0.5) / n;
    for (const double scale : {1e-200, 1e-3, 1.0, 7.5e4, 1e200}) {
      const double y = scale * std::sin(angle), x = scale * std::cos(angle);
      worst = std::max(worst, std::abs(swarm::fast::fast_atan2(y, x) - std::atan2(y, x)));
    }
  }
  for (const double x : {1.0, -1.0, 0.0})
    for (const double y : {1.0, -1.0, 0.0})
      if (x != 0 || y != 0)
        worst = std::max(worst, std::abs(swarm::fast::fast_atan2(y, x) - std::atan2(y, x)));
  MESSAGE("largest atan2 error " << worst);
  CHECK(worst <= swarm::fast::kAtanError);
  CHECK(worst > 0);  // an approximation, not the library call
}

TEST_CASE("fast_log stays within kLogError of log from subnormals to the largest double") {
  double worst = 0;
  for (double x = 4.9e-324; std::isfinite(x); x *= 1.0001) {
    worst = std::max(worst, std::abs(swarm::fast::fast_log(x) - std::log(x)));
    if (x < 1e-300) x *= 1e3;  // the subnormal range takes the library path; skim it
  }
  for (int i = 0; i <= 100000; ++i) {
    const double x = 0.5 + i * 1e-5;  // densely through the mantissa range, both sides of sqrt 2
    worst = std::max(worst, std::abs(swarm::fast::fast_log(x) - std::log(x)));
    worst = std::max(worst, std::abs(swarm::fast::fast_log(2 * x) - std::log(2 * x)));
  }
  MESSAGE("largest log error " << worst);
  CHECK(worst <= swarm::fast::kLogError);
  CHECK(swarm::fast::fast_log(1.0) == 0.0);
  CHECK(std::isinf(swarm::fast::fast_log(0.0)));
}
