#include "swarm/physics/orbit_ahead.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace swarm;

namespace {

/// Two unit masses on a circle of radius 1/2 about their CM, J = 1 (omega = sqrt(2)), the
/// whole pair drifting with velocity V: particle 0 is exactly at
/// R0 + V t + (cos(omega t), sin(omega t), 0) / 2.
System drifting_circle(const Vec3& R0, const Vec3& V) {
  const double w = std::sqrt(2.0);
  System s;
  s.J = 1.0;
  s.particles = {{1.0, R0 + Vec3(0.5, 0, 0), V + Vec3(0, 0.5 * w, 0)},
                 {1.0, R0 + Vec3(-0.5, 0, 0), V + Vec3(0, -0.5 * w, 0)}};
  return s;
}

}  // namespace

TEST_CASE("the orbit ahead follows the exact circle about a moving centre of mass") {
  const Vec3 R0(1, 2, 3), V(0.3, -0.1, 0.2);
  const System s = drifting_circle(R0, V);
  const double w = std::sqrt(2.0), period = 2 * M_PI / w;
  const std::vector<Vec3> path = OrbitsAhead(s).path(s.particles[0], period, 40);
  REQUIRE(path.size() == 41);
  for (int k = 0; k <= 40; ++k) {
    const double t = period * k / 40;
    const Vec3 exact = R0 + V * t + 0.5 * Vec3(std::cos(w * t), std::sin(w * t), 0);
    CHECK((path[std::size_t(k)] - exact).norm() < 1e-12);
  }
}

TEST_CASE("the orbit ahead is a straight line when J = 0 and a cosh/sinh runaway when J < 0") {
  System s = drifting_circle(Vec3::Zero(), Vec3::Zero());
  s.J = 0;
  const Particle& p = s.particles[0];
  const std::vector<Vec3> line = OrbitsAhead(s).path(p, 2.0, 4);
  for (int k = 0; k <= 4; ++k) CHECK((line[std::size_t(k)] - (p.r + p.v * 0.5 * k)).norm() < 1e-14);

  // J = -1: k = -2, Omega = sqrt(2); about the CM at rest x(t) = x0 cosh(Omega t) +
  // u0 sinh(Omega t) / Omega.
  s.J = -1;
  const double W = std::sqrt(2.0);
  const std::vector<Vec3> runaway = OrbitsAhead(s).path(p, 1.0, 10);
  for (int k = 0; k <= 10; ++k) {
    const double t = 0.1 * k;
    const Vec3 exact = p.r * std::cosh(W * t) + p.v * std::sinh(W * t) / W;
    CHECK((runaway[std::size_t(k)] - exact).norm() < 1e-12 * (1 + exact.norm()));
  }
}
