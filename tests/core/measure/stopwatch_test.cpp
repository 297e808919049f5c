#include "swarm/measure/stopwatch.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace swarm;
using doctest::Approx;

TEST_CASE("the stopwatch counts simulated time while running, and only then") {
  Stopwatch w;
  CHECK(!w.running());
  w.observe(1.0);
  CHECK(w.elapsed() == 0);  // stopped: the clock moving adds nothing
  w.start(1.0);
  CHECK(w.running());
  w.observe(1.5);
  w.observe(2.25);
  CHECK(w.elapsed() == Approx(1.25));
  // A paused simulation: the clock does not move, neither does the stopwatch.
  w.observe(2.25);
  w.observe(2.25);
  CHECK(w.elapsed() == Approx(1.25));
  w.lap(3.0);
  w.observe(4.0);
  w.lap(4.5);
  REQUIRE(w.laps().size() == 2);
  CHECK(w.laps()[0] == Approx(2.0));
  CHECK(w.laps()[1] == Approx(3.5));
  w.stop(5.0);
  CHECK(!w.running());
  CHECK(w.elapsed() == Approx(4.0));
  w.observe(9.0);
  CHECK(w.elapsed() == Approx(4.0));
  // Started again, it carries on from its reading, like a real one.
  w.start(10.0);
  w.observe(10.5);
  CHECK(w.elapsed() == Approx(4.5));
  w.reset();
  CHECK(!w.running());
  CHECK(w.elapsed() == 0);
  CHECK(w.laps().empty());
}

TEST_CASE("a clock that goes back adds nothing to the stopwatch") {
  Stopwatch w;
  w.start(5.0);
  w.observe(6.0);
  w.observe(0.0);  // the run restarted
  w.observe(0.5);
  CHECK(w.elapsed() == Approx(1.5));
}

TEST_CASE("stopwatch time in periods 2 pi / omega, none without a period") {
  const double k = 4.0;  // omega = 2: the period is pi
  REQUIRE(in_periods(M_PI, k).has_value());
  CHECK(*in_periods(M_PI, k) == Approx(1.0));
  CHECK(*in_periods(2.5 * M_PI, k) == Approx(2.5));
  CHECK(!in_periods(1.0, 0.0).has_value());
  CHECK(!in_periods(1.0, -4.0).has_value());
}
