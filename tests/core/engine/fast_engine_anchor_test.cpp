#include "engine/fast_engine_anchor.h"

#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "swarm/physics/flow.h"

using namespace swarm;

namespace {

/// The largest distance from the fit's centre of the offset it leaves, P(tau) - F(tau), on a
/// fine grid over [0, horizon] (P: the parabola it was given; F = xc A + xs B).
double largest_left(const fast::OffsetFit& fit, const Vec3& offset, const Vec3& v,
                    const Vec3& acc, double k, double horizon) {
  double largest = 0;
  for (int j = 0; j <= 1000; ++j) {
    const double tau = horizon * j / 1000;
    const Flow f = Flow::over(k, tau);
    const Vec3 P = offset + tau * v + (0.5 * tau * tau) * acc;
    largest = std::max(largest, (P - f.c * fit.A - f.s * fit.B - fit.centre).norm());
  }
  return largest;
}

}  // namespace

TEST_CASE("an off-centre anchor's free oscillation absorbs the CM's parabola over its horizon") {
  // The gravity benchmark's swarm: the CM 0.3 below the centre, falling at 0.2, g = 0.5.
  const Vec3 offset(0.01, 0, -0.3), v(0.02, 0, -0.2), g(0, 0, -0.5);
  SUBCASE("J > 0") {
    // omega = 1 over 1.5 time units: the parabola moves 0.86; what the fit leaves is about a
    // hundredth (0.012), where F matched to the parabola's start alone would leave v tau^3 / 6
    // + g tau^4 / 24, about 0.2, at the horizon; the samples' residual bounds it between them.
    const double k = 1, horizon = 1.5;
    const fast::OffsetFit fit = fast::fit_offset_path(offset, v, g, Vec3::Zero(), k, horizon);
    const double left = largest_left(fit, offset, v, g, k, horizon);
    CHECK(fit.residual < 0.015);
    CHECK(left <= 1.2 * fit.residual);
    const double travel = (horizon * v + 0.5 * horizon * horizon * g).norm();
    CHECK(left < 0.02 * travel);
  }
  SUBCASE("J = 0") {
    // A free oscillation is a straight line: it takes the velocity, the fit the constant, and
    // a quadratic a tau^2 / 2 is left to within about a h^2 / 16 of it.
    const double k = 0, horizon = 1.28;
    const fast::OffsetFit fit = fast::fit_offset_path(offset, v, g, Vec3::Zero(), k, horizon);
    const double left = largest_left(fit, offset, v, g, k, horizon);
    const double bound = 0.5 * horizon * horizon / 16;
    CHECK(left <= 1.6 * bound);
    CHECK(left <= 1.2 * fit.residual);
    CHECK(fit.A.norm() == 0);
  }
  SUBCASE("no horizon: the offset itself") {
    const fast::OffsetFit fit = fast::fit_offset_path(offset, v, g, Vec3::Zero(), 1, 0);
    CHECK(fit.centre == offset);
    CHECK(fit.residual == 0);
  }
}

TEST_CASE("an off-centre anchor's forecast takes in the wall's steady push on the CM") {
  // The swarm pressed onto the wall: the wall pushes the CM up by a = 0.4 (against g = 0.5).
  // The push kicks the CM and, equally, Y (the particles' mean oscillation coordinate), so the
  // anchor's offset R_cm - Y moves by the push's effect on R_cm (a tau^2 / 2) less that on Y, an
  // oscillator of k driven by a from rest. Both integrated here step by step (velocity Verlet,
  // 150,000 steps), independently of the fit's closed form.
  const Vec3 offset(0.01, 0, -0.3), v(0.02, 0, -0.05), g(0, 0, -0.5), push(0, 0, 0.4);
  const double k = 1, horizon = 1.5;
  constexpr int kSteps = 150000;
  const double h = horizon / kSteps;
  std::vector<Vec3> path(kSteps + 1);
  Vec3 R = offset, V = v, Z = Vec3::Zero(), W = Vec3::Zero();
  for (int j = 0; j <= kSteps; ++j) {
    path[std::size_t(j)] = R - Z;
    const Vec3 az = push - k * Z;
    R += h * V + (0.5 * h * h) * (g + push);
    V += h * (g + push);
    Z += h * W + (0.5 * h * h) * az;
    W += (0.5 * h) * (az + push - k * Z);
  }
  const auto largest_left_on_path = [&](const fast::OffsetFit& fit) {
    double largest = 0;
    for (int j = 0; j <= kSteps; j += 100) {
      const Flow f = Flow::over(k, h * j);
      largest = std::max(largest,
                         (path[std::size_t(j)] - f.c * fit.A - f.s * fit.B - fit.centre).norm());
    }
    return largest;
  };
  const fast::OffsetFit with_push = fast::fit_offset_path(offset, v, g, push, k, horizon);
  const fast::OffsetFit free_fall = fast::fit_offset_path(offset, v, g, Vec3::Zero(), k, horizon);
  // The fit with the push leaves of the true path what it says it leaves (its residual, to
  // within its sampling); the free-fall forecast misses it by tens of times more.
  CHECK(largest_left_on_path(with_push) <= 1.2 * with_push.residual + 1e-6);
  CHECK(largest_left_on_path(with_push) < 0.005);
  CHECK(largest_left_on_path(free_fall) > 10 * largest_left_on_path(with_push));
  SUBCASE("J = 0: a push moves R_cm and Y alike, and the offset not at all") {
    const fast::OffsetFit a = fast::fit_offset_path(offset, v, g, push, 0, horizon);
    const fast::OffsetFit b = fast::fit_offset_path(offset, v, g, Vec3::Zero(), 0, horizon);
    CHECK(a.centre == b.centre);
    CHECK(a.B == b.B);
  }
}

TEST_CASE("an off-centre anchor holds while its offset stays within its margin of the centre") {
  fast::MarginInputs in;
  in.R = 1;
  in.k = 1;
  in.omega = 1;
  in.off_centre = true;
  in.residual = 0.01;
  const Vec3 centre(0, 0, -0.4);
  const fast::Anchor a = fast::anchor_with_margin(fast::Anchor{}, centre, in);
  CHECK(a.centre == centre);
  // The margin bounds the drift from the centre, not the distance from the container's.
  CHECK(a.margin < 0.1);
  CHECK(a.threshold == doctest::Approx(1 - a.margin));
  CHECK(a.holds(centre + Vec3(0, 0, 0.99 * a.margin), 1));
  CHECK_FALSE(a.holds(centre + Vec3(0, 0, 1.01 * a.margin), 1));
  CHECK_FALSE(a.holds(Vec3::Zero(), 1));  // the centre of the container is 0.4 away
  CHECK_FALSE(a.wants_renewal(centre + Vec3(0.4 * a.margin, 0, 0), 1));
  CHECK(a.wants_renewal(centre + Vec3(0.6 * a.margin, 0, 0), 1));
}
