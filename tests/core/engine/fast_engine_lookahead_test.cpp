#include "engine/fast_engine_lookahead.h"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <random>

using namespace swarm;

namespace {

/// The lookahead of a swarm of size R = 1 under J M = k, the CM at R_cm moving at V_cm, with
/// a floor at floor_z (-infinity: none).
fast::Lookahead prepared(double k, double dt, const Vec3& R_cm, const Vec3& V_cm,
                         double floor_z) {
  fast::SharedMotion motion;
  motion.R_cm = R_cm;
  motion.V_cm = V_cm;
  fast::Lookahead::FlowsAhead flows{};
  for (std::size_t j = 0; j < flows.size(); ++j) flows[j] = ForcedFlow::over(k, 0, double(j) * dt);
  fast::Lookahead lookahead;
  lookahead.prepare(motion, ForcedFlow::over(k, 0, 7 * dt), flows, std::sqrt(std::abs(k)), 1.0,
                    floor_z);
  return lookahead;
}
}  // namespace

TEST_CASE("the lookahead's first step is the one-by-one step, four at a time or not") {
  std::mt19937_64 rng(20261127);
  std::uniform_real_distribution<double> u(-1, 1), radius(0.3, 1.2);
  constexpr fast::StepIndex now = 1000, kSteps = fast::Lookahead::kSteps;
  long compared = 0, reached = 0, differing = 0;
  for (const double k : {-4.0, -0.01, 1.0, 0.0}) {
    for (const double floor_z : {-std::numeric_limits<double>::infinity(), -0.6}) {
      const fast::Lookahead lookahead =
          prepared(k, 0.01, Vec3(0.01, -0.02, 0.003), Vec3(0.3, 0.1, -0.2), floor_z);
      for (int n = 0; n < 3000; ++n) {
        // Orbits from well inside to beyond the wall, moving out or in.
        const Vec3 a = radius(rng) * Vec3(u(rng), u(rng), u(rng)).normalized();
        const Vec3 b = 2 * Vec3(u(rng), u(rng), u(rng));
        for (fast::StepIndex from = now; from <= now + kSteps; from += 3)
          for (fast::StepIndex last = from - 1; last <= now + kSteps; last += 5) {
            const fast::StepIndex one = lookahead.first_reach_one_by_one(a, b, from, last, now);
            const fast::StepIndex any = lookahead.first_reach(a, b, from, last, now);
            CHECK(one >= from);
            CHECK(one <= last + 1);
            ++compared;
            reached += one <= last;
            differing += one != any;
          }
      }
    }
  }
  INFO("four at once: " << fast::Lookahead::uses_avx2() << ", reached in " << reached << " of "
                        << compared);
  CHECK(differing == 0);
  // Both outcomes are common, so the comparison covers the first lane, the later lanes and none.
  CHECK(reached > compared / 10);
  CHECK(reached < compared * 9 / 10);
}

TEST_CASE("the lookahead finds the first step at or beyond its limit, and not before") {
  // J < 0, a particle on a straight outward run from the CM at rest: the first step it reaches
  // must be one whose predicted |r| is at or beyond the limit, the step before must not be.
  constexpr double k = -1.0, dt = 0.05;
  const fast::Lookahead lookahead = prepared(k, dt, Vec3::Zero(), Vec3::Zero(), -1e300);
  constexpr fast::StepIndex now = 0;
  for (double speed = 0.2; speed < 3; speed += 0.1) {
    const Vec3 a(0.1, 0.2, 0.0), b = speed * Vec3(0.6, 0.8, 0.0);
    const fast::StepIndex first = lookahead.first_reach(a, b, now, now + 16, now);
    const fast::StepIndex one = lookahead.first_reach_one_by_one(a, b, now, now + 16, now);
    CHECK(first == one);
    const auto r_at = [&](fast::StepIndex m) {
      const ForcedFlow f = ForcedFlow::over(k, 0, double(7 + m) * dt);
      return (f.xc * a + f.xs * b).norm();
    };
    if (first <= now + 16) {
      // The limit is the wall (R = 1) less the kicks' slack, 0.021 here: reached means at
      // 0.979 or beyond, and the step before short of it.
      CHECK(r_at(first) > 0.97);
      if (first > now) CHECK(r_at(first - 1) < 0.99);
    } else {
      CHECK(r_at(now + 16) < 1.0);
    }
  }
}
