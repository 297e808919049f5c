#include "swarm/measure/thermometry.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace swarm;
using doctest::Approx;

TEST_CASE("wall pressure and temperature follow the paper's definitions, by hand") {
  // One particle of mass 2 hits the wall head-on at speed 3 with tangential speed 4.
  Particle p{2.0, {0, 0, 1}, {4, 0, 3}};
  WallTally t;
  reflect_at_wall(p, t);
  CHECK(t.hits == 1);
  CHECK(t.radial_impulse == Approx(2 * 2.0 * 3));
  CHECK(t.hit_kinetic_energy == Approx(0.5 * 2.0 * 25));
  CHECK((p.v - Vec3(4, 0, -3)).norm() < 1e-15);
  CHECK((t.wall_momentum - Vec3(0, 0, 12)).norm() < 1e-15);

  WallMeter meter;
  const double R = 2.0, dt = 0.01;
  meter.add(t, dt, sphere_area(R));
  meter.add(WallTally{}, dt, sphere_area(R));
  const WallReading w = meter.reading();
  CHECK(w.P == Approx(12.0 / (4 * M_PI * R * R * 2 * dt)));
  CHECK(w.T == Approx(0.5 * 25.0));  // half the hitters' mean kinetic energy (k_B = 1)
  meter.reset();
  CHECK(meter.reading().P == 0);
  CHECK(meter.reading().T == 0);
}

namespace {

/// Four intervals by hand; the second and the fourth had no wall hit.
std::vector<WallInterval> intervals_with_gaps() {
  return {{1.0, 1.0, {2.0, 3.0, 4}},
          {2.0, 1.0, {1.0, 0.0, 0}},
          {2.5, 0.5, {4.0, 6.0, 2}},
          {3.5, 1.0, {0.0, 0.0, 0}}};
}

void check_reading(const WallReading& w, double P, double T, std::int64_t hits) {
  CHECK(w.P == Approx(P));
  CHECK(w.T == Approx(T));
  CHECK(w.hits == hits);
}

}  // namespace

TEST_CASE("the wall average weighs P by time and T by hits; hitless intervals add nothing to T") {
  const std::vector<WallInterval> in = intervals_with_gaps();
  // P: impulse per area 2*1 + 1*1 + 4*0.5 + 0 = 5 over 3.5 time units. T: 4 hits at 3 and 2
  // at 6 give (12 + 12) / 6 = 4; the unweighted mean over intervals with hits would be 4.5 and
  // counting the hitless ones as T = 0 would give 2.25.
  check_reading(wall_average(in, 0, 4), 5.0 / 3.5, 4.0, 6);
  check_reading(wall_average(in, 1, 2), 1.0, 0.0, 0);  // nothing hit: T = 0 by convention
  check_reading(wall_average(in, 1, 3), 3.0 / 1.5, 6.0, 2);
}

TEST_CASE("windowed wall averages: trailing, centred and zero windows, by hand") {
  const std::vector<WallInterval> in = intervals_with_gaps();
  // Trailing 1.5: the intervals ending in (t - 1.5, t].
  const std::vector<WallReading> trailing = windowed_wall_averages(in, 1.5, 0);
  REQUIRE(trailing.size() == 4);
  check_reading(trailing[0], 2.0, 3.0, 4);        // {0}
  check_reading(trailing[1], 3.0 / 2.0, 3.0, 4);  // {0, 1}: the hitless one leaves T at 3
  check_reading(trailing[2], 3.0 / 1.5, 6.0, 2);  // {1, 2}
  check_reading(trailing[3], 2.0 / 1.5, 6.0, 2);  // {2, 3}: interval 1 ends at 2, outside
  // Centred, 1 either side: the intervals ending in (t - 1, t + 1].
  const std::vector<WallReading> centred = windowed_wall_averages(in, 1, 1);
  check_reading(centred[0], 3.0 / 2.0, 3.0, 4);  // {0, 1}
  check_reading(centred[1], 3.0 / 1.5, 6.0, 2);  // {1, 2}
  check_reading(centred[2], 3.0 / 2.5, 6.0, 2);  // {1, 2, 3}
  check_reading(centred[3], 0.0, 0.0, 0);        // {3}: no hit in the window, so T = 0
  // No window: every interval's own reading.
  const std::vector<WallReading> own = windowed_wall_averages(in, 0, 0);
  for (std::size_t i = 0; i < in.size(); ++i)
    check_reading(own[i], in[i].reading.P, in[i].reading.T, in[i].reading.hits);
}

TEST_CASE("the wall average of intervals equals one meter over all of their steps") {
  // Steps with and without hits, split into three intervals; the container grows in between,
  // as in an expansion, so the per-step area matters.
  const WallTally hit{3, 6.0, 9.0, Vec3::Zero()}, none{};
  const WallTally steps[] = {hit, none, none, hit, none, hit, hit, none, none};
  const double dt = 0.1, radius[] = {1.0, 1.5, 2.0};
  WallMeter whole, part;
  std::vector<WallInterval> intervals;
  for (int i = 0; i < 9; ++i) {
    whole.add(steps[i], dt, radius[i / 3]);
    part.add(steps[i], dt, radius[i / 3]);
    if (i % 3 == 2) {
      intervals.push_back({dt * (i + 1), 3 * dt, part.reading()});  // three steps each
      part.reset();
    }
  }
  const WallReading expected = whole.reading();
  check_reading(wall_average(intervals, 0, intervals.size()), expected.P, expected.T,
                expected.hits);
}

TEST_CASE("wall_estimate: P and T over a trailing window with batch-means standard errors") {
  // Eight intervals of unit length with made-up readings; the window of the last 6 holds
  // intervals 2..7, cut into 3 sub-windows of two intervals each.
  std::vector<WallInterval> intervals;
  const double P[8] = {9, 9, 1.0, 2.0, 4.0, 3.0, 2.5, 1.5};
  const double T[8] = {9, 9, 0.5, 0.7, 0.6, 0.0, 0.9, 0.8};
  const std::int64_t hits[8] = {5, 5, 2, 3, 1, 0, 4, 2};
  for (int i = 0; i < 8; ++i) intervals.push_back({double(i + 1), 1.0, {P[i], T[i], hits[i]}});

  const WallEstimate e = wall_estimate(intervals, 6.0, 3);
  CHECK(e.intervals == 6);
  CHECK(e.blocks == 3);
  CHECK(e.window == Approx(6.0));
  // By hand: P is the time-weighted mean, T the hit-weighted mean.
  CHECK(e.mean.P == Approx((1.0 + 2.0 + 4.0 + 3.0 + 2.5 + 1.5) / 6));
  CHECK(e.mean.T == Approx((0.5 * 2 + 0.7 * 3 + 0.6 * 1 + 0.9 * 4 + 0.8 * 2) / 12));
  CHECK(e.mean.hits == 12);
  // Sub-window values: P 1.5, 3.5, 2.0; T (1 + 2.1) / 5 = 0.62, 0.6 (the hitless interval
  // adds nothing), (3.6 + 1.6) / 6.
  const double bp[3] = {1.5, 3.5, 2.0}, bt[3] = {3.1 / 5, 0.6, 5.2 / 6};
  auto stderr_of = [](const double* v) {
    const double mean = (v[0] + v[1] + v[2]) / 3;
    double s = 0;
    for (int i = 0; i < 3; ++i) s += (v[i] - mean) * (v[i] - mean);
    return std::sqrt(s / 2 / 3);
  };
  REQUIRE(e.P_stderr.has_value());
  REQUIRE(e.T_stderr.has_value());
  CHECK(*e.P_stderr == Approx(stderr_of(bp)));
  CHECK(*e.T_stderr == Approx(stderr_of(bt)));

  // The whole run when the window is 0; no uncertainty from a single interval.
  CHECK(wall_estimate(intervals, 0, 4).intervals == 8);
  const WallEstimate one = wall_estimate(intervals, 0.5, 8);
  CHECK(one.intervals == 1);
  CHECK(!one.P_stderr.has_value());
  CHECK(one.mean.P == Approx(1.5));
  CHECK(wall_estimate({}, 1.0).intervals == 0);
}
