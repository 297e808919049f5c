#include "swarm/physics/analytic.h"

#include <doctest/doctest.h>

#include <cmath>

#include "swarm/methods/integrators.h"
#include "swarm/physics/diagnostics.h"
#include "swarm/physics/regime.h"
#include "swarm/run/side_by_side.h"
#include "test_systems.h"

using namespace swarm;
using doctest::Approx;

TEST_CASE("a circular two-body orbit turns at omega = sqrt(J M)") {
  // Each body circles the CM at distance d_i = d m_j / M; the pair force J m1 m2 d must supply
  // m_i omega^2 d_i, which gives omega^2 = J (m1 + m2) independently of the code.
  const double J = 0.7, m1 = 2, m2 = 3, d = 1.5, M = m1 + m2;
  const double w = std::sqrt(J * M);
  System s;
  s.J = J;
  s.particles = {{m1, {-d * m2 / M, 0, 0}, {0, -w * d * m2 / M, 0}},
                 {m2, {d * m1 / M, 0, 0}, {0, w * d * m1 / M, 0}}};
  const AnalyticSolution exact(s);
  CHECK(exact.omega() == Approx(w).epsilon(1e-15));
  CHECK(exact.period() == Approx(2 * M_PI / w).epsilon(1e-15));

  // Integrate the pairwise force with RK4: the separation must stay d, and after one period
  // 2 pi / sqrt(J M) every body is back where it started.
  System num = s;
  const int steps = 20000;
  for (int i = 0; i < steps; ++i) {
    step_rk4(num, exact.period() / steps);
    CHECK((num.particles[0].r - num.particles[1].r).norm() == Approx(d).epsilon(1e-9));
  }
  CHECK(max_position_difference(num, s) < 1e-9);
}

TEST_CASE("the analytic state is the oscillator solution about the moving CM, at any t") {
  const System s = testing::four_masses();
  const AnalyticSolution exact(s);
  const double M = 3.25, w = std::sqrt(M);
  Vec3 R0 = Vec3::Zero(), V = Vec3::Zero();
  for (const auto& p : s.particles) R0 += p.m * p.r / M, V += p.m * p.v / M;
  for (double t : {0.0, 0.3, 7.1, -2.5, 1234.5}) {
    const System at = exact.at(t);
    CHECK(at.t == t);
    for (std::size_t i = 0; i < s.particles.size(); ++i) {
      const Vec3 x0 = s.particles[i].r - R0, u0 = s.particles[i].v - V;
      const Vec3 r = R0 + V * t + x0 * std::cos(w * t) + u0 / w * std::sin(w * t);
      const Vec3 v = V - x0 * w * std::sin(w * t) + u0 * std::cos(w * t);
      CHECK((at.particles[i].r - r).norm() < 1e-11 * (1 + std::abs(t)));
      CHECK((at.particles[i].v - v).norm() < 1e-11 * (1 + std::abs(t)));
    }
  }
}

TEST_CASE("orbit parameters A, B and C, D reproduce the initial conditions") {
  const System s = testing::four_masses(1.0);
  const AnalyticSolution a(s);
  const Vec3 R = cm_position(s), V = cm_velocity(s);
  for (std::size_t i = 0; i < 4; ++i) {
    const OrbitParameters o = a.orbit(i);
    CHECK((o.A - (s.particles[i].r - R)).norm() < 1e-14);
    CHECK((o.B * a.omega() - (s.particles[i].v - V)).norm() < 1e-14);
  }
  const System rep = testing::four_masses(-1.0);
  const AnalyticSolution b(rep);
  for (std::size_t i = 0; i < 4; ++i) {
    const OrbitParameters o = b.orbit(i);
    CHECK((o.C + o.D - (rep.particles[i].r - R)).norm() < 1e-13);
    CHECK(((o.C - o.D) * b.omega() - (rep.particles[i].v - V)).norm() < 1e-13);
  }
}

TEST_CASE("every attractive orbit is a closed ellipse with the common period") {
  const System s = testing::four_masses(0.4);
  const AnalyticSolution a(s);
  const System later = a.at(a.period());
  for (std::size_t i = 0; i < 4; ++i) {
    const Vec3 shift = a.cm_velocity() * a.period();  // the CM moves on
    CHECK((later.particles[i].r - shift - s.particles[i].r).norm() < 1e-12);
    const OrbitEllipse e = ellipse_of(a.orbit(i).A, a.orbit(i).B);
    const double sa = e.semi_major.norm(), sb = e.semi_minor.norm();
    CHECK(sa >= sb);
    CHECK(std::abs(e.semi_major.dot(e.semi_minor)) < 1e-12 * sa * sa);
    for (double t = 0; t < a.period(); t += a.period() / 17) {
      const Vec3 x = a.particle_at(i, t).r - a.cm_position_at(t);
      const double p = x.dot(e.semi_major) / sa, q = sb > 0 ? x.dot(e.semi_minor) / sb : 0;
      CHECK(p * p / (sa * sa) + q * q / (sb * sb) == Approx(1.0).epsilon(1e-10));
    }
  }
}

TEST_CASE("repulsive separation grows as exp(Omega t)") {
  const double J = -0.5, m = 1.0;
  System s;
  s.J = J;
  s.particles = {{m, {-0.5, 0, 0}, {0, 0, 0}}, {m, {0.5, 0, 0}, {0, 0, 0}}};
  const double Omega = std::sqrt(-J * 2 * m);
  const AnalyticSolution a(s);
  CHECK(a.omega() == Approx(Omega));
  // From rest the separation is d0 cosh(Omega t).
  for (double t : {0.5, 2.0, 10.0}) {
    const System at = a.at(t);
    const double d = (at.particles[1].r - at.particles[0].r).norm();
    CHECK(d == Approx(std::cosh(Omega * t)).epsilon(1e-12));
  }
  // The pairwise integration agrees on the growth rate.
  System num = s;
  for (int i = 0; i < 4000; ++i) step_rk4(num, 1e-3);
  const double d4 = (num.particles[1].r - num.particles[0].r).norm();
  CHECK(std::log(d4) == Approx(std::log(std::cosh(4 * Omega))).epsilon(1e-9));
}

TEST_CASE("J = 0 is free motion and one particle alone moves uniformly") {
  System s = testing::four_masses(0.0);
  const AnalyticSolution a(s);
  const System at = a.at(3.0);
  for (std::size_t i = 0; i < 4; ++i)
    CHECK((at.particles[i].r - (s.particles[i].r + 3.0 * s.particles[i].v)).norm() < 1e-13);
  CHECK(std::isinf(a.period()));

  for (double J : {2.0, 0.0, -2.0}) {
    System one;
    one.J = J;
    one.particles = {{2.0, {1, 2, 3}, {0.5, -1, 0}}};
    System stepped = one;
    for (int i = 0; i < 100; ++i) step_analytic(stepped, 0.1);
    CHECK((stepped.particles[0].r - Vec3(6, -8, 3)).norm() < 1e-12);
    for (Method m : {Method::euler, Method::euler_cromer, Method::verlet, Method::rk4}) {
      System n = one;
      for (int i = 0; i < 10; ++i) step(m, n, 0.1);
      CHECK((n.particles[0].r - Vec3(1.5, 1, 3)).norm() < 1e-12);
    }
  }
}

TEST_CASE("the per-step analytic map conserves energy, momentum and angular momentum") {
  for (double J : {1.0, -0.3}) {
    System s = testing::four_masses(J);
    const double E0 = total_energy(s);
    const Vec3 P0 = total_momentum(s), L0 = angular_momentum_cm(s);
    for (int i = 0; i < 2000; ++i) step_analytic(s, 1e-3);
    CHECK(total_energy(s) == Approx(E0).epsilon(1e-12));
    CHECK((total_momentum(s) - P0).norm() < 1e-12);
    CHECK((angular_momentum_cm(s) - L0).norm() < 1e-11 * L0.norm());
  }
}
