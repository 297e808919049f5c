#include "swarm/measure/wall_tally_log.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "swarm/measure/thermometry.h"

using namespace swarm;
using doctest::Approx;

namespace {

/// The log keeps its steps in blocks of 4096 (WallTallyLog::kBlock, private): stretches are
/// read across those seams below.
constexpr long kSeam = 4096;

/// A made-up but physical tally for step i: 0 to 3 hits, and impulse and kinetic energy only
/// when something hit. Values are multiples of 1/8, so the test's own sums are exact.
WallTally tally_of_step(long i, double scale = 1.0) {
  WallTally t;
  t.hits = (i * 7 + i / 5) % 4;
  t.radial_impulse = scale * double(t.hits) * (1 + double(i % 13) * 0.25);
  t.hit_kinetic_energy = scale * double(t.hits) * (0.5 + double(i % 5) * 0.125);
  // Fields the log does not keep, which must not leak into its readings.
  t.wall_momentum = Vec3(1, 2, 3);
  t.floor_hits = 5;
  return t;
}

/// The paper's definitions over steps [first, last) of tally_of_step, computed here: P is the
/// total impulse over the wall's area 4 pi R^2 and the stretch's time (last - first) dt, T half
/// the hitters' mean kinetic energy, and both 0 when there is nothing to divide by.
WallReading expected_reading(long first, long last, double dt, double R, double scale = 1.0) {
  std::int64_t hits = 0;
  double impulse = 0, energy = 0;
  for (long i = first; i < last; ++i) {
    const WallTally t = tally_of_step(i, scale);
    hits += t.hits;
    impulse += t.radial_impulse;
    energy += t.hit_kinetic_energy;
  }
  WallReading w;
  w.hits = hits;
  if (last > first) w.P = impulse / (4 * M_PI * R * R) / (double(last - first) * dt);
  if (hits > 0) w.T = 0.5 * energy / double(hits);
  return w;
}

void check_same(const WallReading& got, const WallReading& expected) {
  CHECK(got.hits == expected.hits);
  CHECK(got.P == Approx(expected.P).epsilon(1e-12));
  CHECK(got.T == Approx(expected.T).epsilon(1e-12));
}

}  // namespace

TEST_CASE("wall tally log: an empty log, and a stretch of no steps, read all zeros") {
  WallTallyLog log;
  CHECK(log.size() == 0);
  const WallReading empty = log.reading(0, 1e-3, sphere_area(1.0));
  CHECK(empty.hits == 0);
  CHECK(empty.P == 0);
  CHECK(empty.T == 0);
  for (long i = 0; i < 10; ++i) log.push(tally_of_step(i));
  const WallReading none = log.reading(log.size(), 1e-3, 1.0);
  CHECK(none.hits == 0);
  CHECK(none.P == 0);
  CHECK(none.T == 0);
}

TEST_CASE(
    "wall tally log: a stretch's reading is the sum of the tallies fed in, wherever it starts") {
  WallTallyLog log;
  const long n = 3 * kSeam + 1000;
  for (long i = 0; i < n; ++i) {
    log.push(tally_of_step(i));
    REQUIRE(log.size() == i + 1);
  }
  const double dt = 2e-3, R = 1.5;
  // Starts at the ends and on either side of every seam, ...
  std::vector<long> firsts = {0, 1, n - 2, n - 1, n};
  for (long seam = kSeam; seam < n; seam += kSeam)
    for (long first : {seam - 1, seam, seam + 1}) firsts.push_back(first);
  // ... and some of no particular kind.
  std::uint64_t x = 12345;
  for (int i = 0; i < 8; ++i) {
    x = (x * 1103515245 + 12345) % 2147483648;
    firsts.push_back(long(x % std::uint64_t(n + 1)));
  }
  for (long first : firsts) {
    CAPTURE(first);
    check_same(log.reading(first, dt, sphere_area(R)), expected_reading(first, n, dt, R));
  }
  // dt and the area are the reader's: P goes as 1 / (dt area), T and the hits do not change.
  check_same(log.reading(kSeam - 3, 0.5, sphere_area(0.25)), expected_reading(kSeam - 3, n, 0.5, 0.25));
}

TEST_CASE("wall tally log: reads as one WallMeter fed the same steps, to the bit") {
  // The header's promise: the log stands in for a meter that was started at `first`.
  WallTallyLog log;
  const long n = kSeam + 300;
  const double dt = 1e-3, R = 0.7;
  for (long i = 0; i < n; ++i) log.push(tally_of_step(i));
  for (long first : {0L, 17L, kSeam - 1, kSeam, n - 1}) {
    CAPTURE(first);
    WallMeter meter;
    for (long i = first; i < n; ++i) meter.add(tally_of_step(i), dt, sphere_area(R));
    const WallReading a = log.reading(first, dt, sphere_area(R)), b = meter.reading();
    CHECK(a.hits == b.hits);
    CHECK(a.P == b.P);
    CHECK(a.T == b.T);
  }
}

TEST_CASE("wall tally log: readings are right as the log grows through a block's seam") {
  WallTallyLog log;
  const double dt = 1e-3, R = 1.0;
  for (long i = 0; i < kSeam + 2; ++i) {
    log.push(tally_of_step(i));
    const long size = i + 1;
    if (size < kSeam - 2 && size > 3) continue;
    CAPTURE(size);
    check_same(log.reading(0, dt, sphere_area(R)), expected_reading(0, size, dt, R));
    check_same(log.reading(size - 1, dt, sphere_area(R)), expected_reading(size - 1, size, dt, R));
  }
}

TEST_CASE("wall tally log: a stretch where nothing hit has no temperature and no pressure") {
  WallTallyLog log;
  for (long i = 0; i < 5; ++i) log.push(tally_of_step(i));
  for (int i = 0; i < 7; ++i) log.push(WallTally{});
  const WallReading quiet = log.reading(5, 1e-3, sphere_area(1.0));
  CHECK(quiet.hits == 0);
  CHECK(quiet.T == 0);
  CHECK(quiet.P == 0);
  // The quiet steps still count as time: the pressure over all of them is diluted.
  check_same(log.reading(0, 1e-3, sphere_area(1.0)), [] {
    WallReading w = expected_reading(0, 5, 1e-3, 1.0);
    w.P *= 5.0 / 12.0;
    return w;
  }());
}

TEST_CASE("wall tally log: copies are independent, whether cut inside a block or at its seam") {
  const double dt = 1e-3, R = 1.0;
  for (long cut : {kSeam + 100, kSeam, 2 * kSeam}) {
    CAPTURE(cut);
    WallTallyLog original;
    for (long i = 0; i < cut; ++i) original.push(tally_of_step(i));
    WallTallyLog copy = original;
    CHECK(copy.size() == cut);
    // Each goes on with its own steps (the copy's ten times larger) past the next seam.
    const long more = kSeam + 50;
    for (long i = cut; i < cut + more; ++i) {
      original.push(tally_of_step(i));
      copy.push(tally_of_step(i, 10.0));
    }
    REQUIRE(original.size() == cut + more);
    REQUIRE(copy.size() == cut + more);
    // The shared history reads alike, what followed reads as each was fed.
    check_same(original.reading(0, dt, sphere_area(R)), expected_reading(0, cut + more, dt, R));
    const WallReading shared = expected_reading(0, cut, dt, R);
    const WallReading own = expected_reading(cut, cut + more, dt, R, 10.0);
    const WallReading copy_all = copy.reading(0, dt, sphere_area(R));
    CHECK(copy_all.hits == shared.hits + own.hits);
    // P sums impulse per time: weigh each part by its number of steps.
    CHECK(copy_all.P == Approx((shared.P * double(cut) + own.P * double(more)) / double(cut + more))
                            .epsilon(1e-12));
    CHECK(copy_all.T == Approx((shared.T * double(shared.hits) + own.T * double(own.hits)) /
                               double(shared.hits + own.hits))
                            .epsilon(1e-12));
    check_same(copy.reading(cut, dt, sphere_area(R)), own);
    // Clearing one leaves the other whole.
    copy.clear();
    CHECK(copy.size() == 0);
    check_same(original.reading(0, dt, sphere_area(R)), expected_reading(0, cut + more, dt, R));
  }
}

TEST_CASE("wall tally log: after clear() it reads as a new log") {
  WallTallyLog log;
  for (long i = 0; i < kSeam + 10; ++i) log.push(tally_of_step(i, 3.0));
  log.clear();
  CHECK(log.size() == 0);
  const WallReading empty = log.reading(0, 1e-3, sphere_area(1.0));
  CHECK(empty.hits == 0);
  CHECK(empty.P == 0);
  for (long i = 0; i < kSeam + 10; ++i) log.push(tally_of_step(i));
  check_same(log.reading(0, 1e-3, sphere_area(1.0)), expected_reading(0, kSeam + 10, 1e-3, 1.0));
  check_same(log.reading(kSeam, 1e-3, sphere_area(1.0)), expected_reading(kSeam, kSeam + 10, 1e-3, 1.0));
}
