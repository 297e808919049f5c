#include "plotting/decimate.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <initializer_list>
#include <vector>

using namespace swarmlab::plotting;

namespace {

/// A noisy signal with isolated spikes, as the wall pressure looks sample by sample.
XY spiky_series(std::size_t n) {
  XY s;
  for (std::size_t i = 0; i < n; ++i) {
    s.x.push_back(0.01 * double(i));
    double y = std::sin(0.003 * double(i)) + 0.1 * std::sin(1.7 * double(i));
    if (i % 997 == 13) y += 5;  // a spike
    if (i % 1499 == 700) y -= 4;
    s.y.push_back(y);
  }
  return s;
}

}  // namespace

TEST_CASE("short series, and asks for fewer than four points, come back unchanged") {
  const XY s = spiky_series(500);
  for (std::size_t max_points : {500, 501, 10000}) {
    const XY d = decimated(s.x, s.y, max_points);
    CHECK(d.x == s.x);
    CHECK(d.y == s.y);
  }
  for (std::size_t max_points : {0, 1, 3}) CHECK(decimated(s.x, s.y, max_points).x == s.x);
  const XY empty = decimated({}, {}, 10);
  CHECK(empty.x.empty());
  CHECK(empty.y.empty());
}

TEST_CASE("a long series keeps at most max_points points, each bucket's extremes in order") {
  for (std::size_t n : {std::size_t(501), std::size_t(4001), std::size_t(100000)})
    for (std::size_t max_points : {4, 5, 100, 500}) {
      CAPTURE(n);
      CAPTURE(max_points);
      const XY s = spiky_series(n);
      const XY d = decimated(s.x, s.y, max_points);
      REQUIRE(d.x.size() == d.y.size());
      CHECK(d.x.size() <= max_points);
      // Each bucket gives one or two points, so at least one per bucket.
      const std::size_t buckets = max_points / 2;
      CHECK(d.x.size() >= buckets);
      // Points of the original series, in time order.
      std::size_t from = 0;
      for (std::size_t j = 0; j < d.x.size(); ++j) {
        const auto at = std::find(s.x.begin() + long(from), s.x.end(), d.x[j]);
        REQUIRE(at != s.x.end());
        const std::size_t i = std::size_t(at - s.x.begin());
        CHECK(s.y[i] == d.y[j]);
        from = i + 1;
      }
      // Bucket b covers points [b n / buckets, (b + 1) n / buckets): its lowest and highest y
      // are both kept.
      for (std::size_t b = 0; b < buckets; ++b) {
        const auto first = s.y.begin() + long(b * n / buckets);
        const auto last = s.y.begin() + long((b + 1) * n / buckets);
        const double x0 = s.x[b * n / buckets], x1 = s.x[(b + 1) * n / buckets - 1];
        double kept_lo = HUGE_VAL, kept_hi = -HUGE_VAL;
        for (std::size_t j = 0; j < d.x.size(); ++j)
          if (d.x[j] >= x0 && d.x[j] <= x1)
            kept_lo = std::min(kept_lo, d.y[j]), kept_hi = std::max(kept_hi, d.y[j]);
        CHECK(kept_lo == *std::min_element(first, last));
        CHECK(kept_hi == *std::max_element(first, last));
      }
    }
}

TEST_CASE("every spike of a long series survives decimation, and so do its extremes") {
  const XY s = spiky_series(200000);
  const XY d = decimated(s.x, s.y, 2000);
  CHECK(*std::max_element(d.y.begin(), d.y.end()) == *std::max_element(s.y.begin(), s.y.end()));
  CHECK(*std::min_element(d.y.begin(), d.y.end()) == *std::min_element(s.y.begin(), s.y.end()));
  std::size_t spikes = 0, kept = 0;
  for (std::size_t i = 0; i < s.y.size(); ++i)
    if (i % 997 == 13) {
      ++spikes;
      kept += std::count(d.x.begin(), d.x.end(), s.x[i]) > 0;
    }
  CHECK(kept == spikes);
  // The kept points span the series to within one bucket at each end.
  const double bucket_width = (s.x.back() - s.x.front()) / 1000;
  CHECK(d.x.front() - s.x.front() < bucket_width);
  CHECK(s.x.back() - d.x.back() < bucket_width);
}
