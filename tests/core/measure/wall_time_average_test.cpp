#include "swarm/measure/wall_time_average.h"

#include <doctest/doctest.h>

#include <cmath>
#include <random>

using namespace swarm;

TEST_CASE("wall time averages: the settling stretch is left out, P over time, T over the hits") {
  // 4,000 intervals of 0.01: P relaxes from 0 towards 10 with time constant 2 (the first 600
  // intervals are far from it), then fluctuates; T is 3 on every hit, with 0-4 hits an interval.
  std::mt19937_64 rng(4);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::uniform_int_distribution<int> hits(0, 4);
  std::vector<WallInterval> intervals;
  for (int i = 0; i < 4000; ++i) {
    const double t = 0.01 * (i + 1);
    const int h = hits(rng);
    intervals.push_back({t, 0.01, {10 * (1 - std::exp(-t / 2)) + noise(rng), h ? 3.0 : 0.0, h}});
  }
  const WallTimeAverages a = wall_time_averages(intervals);
  CHECK(a.start >= 5.99);  // 3 time constants: within 5 % of the end value, below the noise
  CHECK(a.start <= 20.0);
  REQUIRE(a.P);
  REQUIRE(a.T);
  CHECK(std::abs(a.P->mean - 10) < 4 * a.P->se + 0.1);
  CHECK(a.P->se == doctest::Approx(1 / std::sqrt(double(a.intervals))).epsilon(0.2));
  CHECK(a.T->mean == doctest::Approx(3.0));
  CHECK(a.intervals == long(std::lround((40.0 - a.start) / 0.01)));
  CHECK_FALSE(wall_time_averages({intervals.begin(), intervals.begin() + 7}).P);
}
