#include "access/wall_clicks.h"

#include <doctest/doctest.h>

using namespace swarmlab;

TEST_CASE("click_rate: every hit up to 20 a second, then rising slower, never above the cap") {
  CHECK(WallClicks::click_rate(0) == 0);
  CHECK(WallClicks::click_rate(5) == doctest::Approx(5));
  CHECK(WallClicks::click_rate(20) == doctest::Approx(20));
  // 20 (1 + ln(200 / 20) / 2) = 20 (1 + 1.1513) = 43.03
  CHECK(WallClicks::click_rate(200) == doctest::Approx(43.026).epsilon(1e-4));
  CHECK(WallClicks::click_rate(1e9) == doctest::Approx(WallClicks::kMaxClickRate));
  // More hits are heard as more clicks everywhere below the cap: pressure is audible.
  double previous = 0;
  for (double rate = 1; rate < 1000; rate *= 1.5) {
    CAPTURE(rate);
    CHECK(WallClicks::click_rate(rate) > previous);
    previous = WallClicks::click_rate(rate);
  }
}

TEST_CASE("clicks: a lone hit is heard at once") {
  WallClicks w;
  CHECK(w.clicks(0, 1 / 60.0) == 0);
  CHECK(w.clicks(1, 1 / 60.0) == 1);
  CHECK(w.clicks(0, 1 / 60.0) == 0);
}

namespace {

/// Clicks heard over `seconds` of 60 Hz frames at a steady number of hits per frame.
int clicks_over(double seconds, long hits_per_frame) {
  WallClicks w;
  int total = 0;
  const int frames = int(seconds * 60);
  for (int f = 0; f < frames; ++f) total += w.clicks(hits_per_frame, 1 / 60.0);
  return total;
}

}  // namespace

TEST_CASE("clicks: a steady rate is thinned to the heard rate, and more hits give more clicks") {
  // 10 s after a 2 s settling of the averaged rate; one hit a frame = 60 hits/s.
  const double seconds = 10;
  const int low = clicks_over(12, 1) - clicks_over(2, 1);
  CHECK(low == doctest::Approx(WallClicks::click_rate(60) * seconds).epsilon(0.03));
  const int high = clicks_over(12, 50) - clicks_over(2, 50);  // 3000 hits/s
  CHECK(high == doctest::Approx(WallClicks::click_rate(3000) * seconds).epsilon(0.03));
  CHECK(high > low);
  CHECK(high <= WallClicks::kMaxClickRate * seconds);
}

TEST_CASE("clicks: a long frame with a burst of hits gives no burst of clicks") {
  WallClicks w;
  CHECK(w.clicks(100000, 0.5) <= WallClicks::kMaxClickRate * 0.5);
  CHECK(w.clicks(5, 0) == 0);
  CHECK(w.clicks(-3, 0.1) == 0);
}
