#include "swarm/physics/flow.h"

#include <doctest/doctest.h>

#include <cmath>
#include <initializer_list>

#include "oscillator_rk4.h"

using namespace swarm;
using doctest::Approx;
using testing::integrate_oscillator;

namespace {

// Oscillation, free flight and runaway, each at a rate where a few time units matter.
const double kStiffnesses[] = {2.5, 0.04, 0.0, -0.04, -0.7};
const double kTimes[] = {0.0, 0.013, 1.0, 3.7, -2.2};

struct Phase {
  double x, v;
};

Phase applied(const Flow& f, Phase p) { return {f.c * p.x + f.s * p.v, f.dc() * p.x + f.c * p.v}; }

}  // namespace

TEST_CASE("Flow::over moves (x, v) as x'' = -k x integrated step by step does") {
  for (double k : kStiffnesses)
    for (double t : kTimes)
      for (Phase start : {Phase{1, 0}, Phase{0, 1}, Phase{-0.6, 0.35}}) {
        CAPTURE(k);
        CAPTURE(t);
        double x = start.x, v = start.v;
        integrate_oscillator(k, t, 4000, x, v);
        const Phase p = applied(Flow::over(k, t), start);
        CHECK(p.x == Approx(x).epsilon(1e-11).scale(1));
        CHECK(p.v == Approx(v).epsilon(1e-11).scale(1));
      }
}

TEST_CASE("Flow::over is cos and sin/omega, cosh and sinh/Omega, or 1 and t") {
  const double w = 1.5;
  for (double t : kTimes) {
    const Flow a = Flow::over(w * w, t), r = Flow::over(-w * w, t), f = Flow::over(0.0, t);
    CHECK(a.c == Approx(std::cos(w * t)).epsilon(1e-15));
    CHECK(a.s == Approx(std::sin(w * t) / w).epsilon(1e-15));
    CHECK(r.c == Approx(std::cosh(w * t)).epsilon(1e-15));
    CHECK(r.s == Approx(std::sinh(w * t) / w).epsilon(1e-15));
    CHECK(f.c == 1.0);
    CHECK(f.s == t);
    CHECK(f.dc() == 0.0);
    // Velocity from displacement: -omega sin for oscillation, +Omega sinh for runaway.
    CHECK(a.dc() == Approx(-w * std::sin(w * t)).epsilon(1e-15));
    CHECK(r.dc() == Approx(w * std::sinh(w * t)).epsilon(1e-15));
  }
}

TEST_CASE("the flow has determinant 1 and composes: Flow(t1) then Flow(t2) is Flow(t1 + t2)") {
  for (double k : kStiffnesses)
    for (double t1 : kTimes)
      for (double t2 : {0.4, -1.3, 5.0}) {
        CAPTURE(k);
        const Flow a = Flow::over(k, t1), b = Flow::over(k, t2), ab = Flow::over(k, t1 + t2);
        CHECK(a.c * a.c - a.s * a.dc() == Approx(1.0).epsilon(1e-13));
        // [[c, s], [dc, c]] of b times that of a.
        CHECK(b.c * a.c + b.s * a.dc() == Approx(ab.c).epsilon(1e-13).scale(1));
        CHECK(b.c * a.s + b.s * a.c == Approx(ab.s).epsilon(1e-13).scale(1));
        CHECK(b.dc() * a.c + b.c * a.dc() == Approx(ab.dc()).epsilon(1e-13).scale(1));
      }
}

TEST_CASE("the flow conserves the oscillator energy v^2 / 2 + k x^2 / 2") {
  for (double k : kStiffnesses)
    for (double t : kTimes) {
      const Phase start{0.8, -0.3};
      const Phase p = applied(Flow::over(k, t), start);
      const double e0 = 0.5 * start.v * start.v + 0.5 * k * start.x * start.x;
      CHECK(0.5 * p.v * p.v + 0.5 * k * p.x * p.x == Approx(e0).epsilon(1e-13).scale(1));
    }
}

TEST_CASE("a weak spring either way approaches free flight continuously") {
  // No regime switch may jump: at k = +-1e-12 over t = 3 the spring changes x by ~ k t^2 / 2.
  const Flow free = Flow::over(0.0, 3.0);
  for (double k : {1e-12, -1e-12}) {
    const Flow f = Flow::over(k, 3.0);
    CHECK(std::abs(f.c - free.c) < 1e-11);
    CHECK(std::abs(f.s - free.s) < 1e-11);
    CHECK(f.k == k);
  }
}
