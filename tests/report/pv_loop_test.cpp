#include "report/pv_loop.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace swarmlab::report;

TEST_CASE("pv_loop: the P-V loop splits where the wall is innermost, V = 4/3 pi R^3") {
  // The wall goes 2 -> 1 -> 2 at a steady pressure: any running mean of it is the same.
  const double radii[] = {2.0, 1.5, 1.0, 1.5, 2.0};
  std::vector<swarm::Sample> samples;
  for (int i = 0; i < 5; ++i) {
    swarm::Sample s;
    s.t = 0.1 * i;
    s.R = radii[i];
    s.P = 0.75;
    s.hits = 10;
    samples.push_back(s);
  }
  const PvLoop loop = pv_loop(samples, 0.05, 0.0);
  const double pi = std::acos(-1.0);
  // Intervals end at samples 1..4; the innermost is sample 2 (R = 1).
  REQUIRE(loop.V_in.size() == 2);
  CHECK(loop.V_in[0] == doctest::Approx(4.0 / 3.0 * pi * 1.5 * 1.5 * 1.5));
  CHECK(loop.V_in[1] == doctest::Approx(4.0 / 3.0 * pi));
  REQUIRE(loop.V_out.size() == 3);  // joined at the innermost point
  CHECK(loop.V_out[0] == loop.V_in[1]);
  CHECK(loop.V_out[2] == doctest::Approx(4.0 / 3.0 * pi * 8));
  for (double P : loop.P_in) CHECK(P == doctest::Approx(0.75));
  for (double P : loop.P_out) CHECK(P == doctest::Approx(0.75));
}

TEST_CASE("pv_loop: with hard spheres of radius a, V is the ball their centres reach, 4/3 pi (R - a)^3") {
  // The wall's P divides by the sphere of radius R - a (swarm::Run::wall_area), so the loop's
  // V is that ball's: P dV then sums to the wall's work.
  std::vector<swarm::Sample> samples;
  for (double R : {2.0, 1.0, 2.0}) {
    swarm::Sample s;
    s.t = 0.1 * double(samples.size());
    s.R = R;
    s.P = 1.0;
    s.hits = 10;
    samples.push_back(s);
  }
  const PvLoop loop = pv_loop(samples, 0.05, 0.25);
  const double pi = std::acos(-1.0);
  REQUIRE(loop.V_in.size() == 1);
  CHECK(loop.V_in[0] == doctest::Approx(4.0 / 3.0 * pi * 0.75 * 0.75 * 0.75));
  REQUIRE(loop.V_out.size() == 2);
  CHECK(loop.V_out[1] == doctest::Approx(4.0 / 3.0 * pi * 1.75 * 1.75 * 1.75));
}
