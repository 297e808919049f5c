#include "swarm/regime.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace swarm;
using doctest::Approx;

TEST_CASE("natural_time_of is 2 pi / sqrt|k|: the period when attractive, as long when repulsive") {
  // k = 4: omega = 2, the period is pi; k = -4: Omega = 2, and in pi the runaway exp(Omega t)
  // grows by e^(2 pi).
  CHECK(natural_time_of(4.0) == Approx(M_PI));
  CHECK(natural_time_of(4.0) == period_of(4.0));
  CHECK(natural_time_of(-4.0) == Approx(M_PI));
  CHECK(std::isinf(natural_time_of(0.0)));
}
