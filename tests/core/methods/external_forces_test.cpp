#include "swarm/measure/state_hash.h"
#include "swarm/methods/external_forces.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "swarm/methods/integrators.h"
#include "swarm/methods/method.h"
#include "swarm/physics/diagnostics.h"
#include "swarm/physics/gravity.h"
#include "test_systems.h"

using namespace swarm;
using doctest::Approx;

namespace {

/// a_i = -J sum_k m_k (r_i - r_k) + g - c_i v_i, summed plainly over every partner (eq. 1 and
/// Appendix B), so that the library's accelerations are checked against the force law itself.
std::vector<Vec3> expected_accelerations(const System& s, const Vec3& g,
                                         const std::vector<double>& c) {
  std::vector<Vec3> a(s.particles.size(), Vec3::Zero());
  for (std::size_t i = 0; i < s.particles.size(); ++i) {
    for (const Particle& q : s.particles) a[i] -= s.J * q.m * (s.particles[i].r - q.r);
    a[i] += g - c[i] * s.particles[i].v;
  }
  return a;
}

/// The textbook solution of x'' = -k x - gamma x' for x(0) = x0, x'(0) = u0, from the roots
/// of lambda^2 + gamma lambda + k = 0, written out per regime with std:: functions only.
/// Returns {x(t), x'(t)}.
std::pair<double, double> damped(double k, double gamma, double x0, double u0, double t) {
  const double h = gamma / 2, D = h * h - k;
  if (D > 0) {  // two real roots: over-damped, or a damped runaway when k < 0
    const double l1 = -h + std::sqrt(D), l2 = -h - std::sqrt(D);
    const double A = (u0 - l2 * x0) / (l1 - l2), B = x0 - A;
    return {A * std::exp(l1 * t) + B * std::exp(l2 * t),
            A * l1 * std::exp(l1 * t) + B * l2 * std::exp(l2 * t)};
  }
  if (D == 0) {  // a double root -h
    const double x = (x0 + (u0 + h * x0) * t) * std::exp(-h * t);
    return {x, (u0 + h * x0) * std::exp(-h * t) - h * x};
  }
  const double w = std::sqrt(-D), e = std::exp(-h * t);
  const double x = e * (x0 * std::cos(w * t) + (u0 + h * x0) / w * std::sin(w * t));
  return {x, -h * x + e * (-x0 * w * std::sin(w * t) + (u0 + h * x0) * std::cos(w * t))};
}

Vec3 damped_position(double k, double gamma, const Vec3& x0, const Vec3& u0, double t) {
  return {damped(k, gamma, x0.x(), u0.x(), t).first, damped(k, gamma, x0.y(), u0.y(), t).first,
          damped(k, gamma, x0.z(), u0.z(), t).first};
}

/// (1 - exp(-gamma t)) / gamma, the CM's displacement per unit initial velocity under drag,
/// in long double where the platform has more digits than a double.
long double decay_integral(double gamma, double t) {
  return -std::expm1(-(long double)gamma * t) / (long double)gamma;
}

/// (t - (1 - exp(-gamma t)) / gamma) / gamma, the CM's displacement per unit g under drag. For
/// gamma t < 0.01 from its Taylor series t^2 sum (-gamma t)^n / (n + 2)! to n = 7 (the first
/// term left out is below 1e-22 of the sum); above, from the closed form in long double, where
/// the cancellation costs at most a factor 2 / (gamma t) = 200 of its precision.
double free_fall_per_g(double gamma, double t) {
  const double x = gamma * t;
  if (x < 0.01) {
    const double inverse_factorial[] = {1.0 / 2,   1.0 / 6,    1.0 / 24,    1.0 / 120,
                                        1.0 / 720, 1.0 / 5040, 1.0 / 40320, 1.0 / 362880};
    long double sum = 0, power = 1;
    for (double f : inverse_factorial) {
      sum += power * f;
      power *= -x;
    }
    return double((long double)t * t * sum);
  }
  return double(((long double)t - decay_integral(gamma, t)) / (long double)gamma);
}

/// Four masses (M = 3.25) with three-dimensional motion and a moving CM.
System swarm_of_four(double J) { return testing::four_masses(J); }

double max_abs(const Vec3& v) { return v.cwiseAbs().maxCoeff(); }

}  // namespace

TEST_CASE("external forces: any() says whether anything acts from outside") {
  ExternalForces f;
  CHECK_FALSE(f.any());
  f.gravity = Vec3(0, 0, -9.8);
  CHECK(f.any());
  ExternalForces drag_only;
  drag_only.drag = Drag{0.3, 0, {}};
  CHECK(drag_only.any());
}

TEST_CASE("external forces: accelerations are the pairwise pull plus g - c_i v_i") {
  const System s = swarm_of_four(0.7);
  const Vec3 g(0.3, -0.2, -9.8);
  std::vector<Vec3> a;

  SUBCASE("no external force: exactly pairwise_accelerations, to the bit") {
    std::vector<Vec3> pairwise;
    pairwise_accelerations(s, pairwise, 1);
    accelerations(s, ExternalForces{}, a, 1);
    REQUIRE(a.size() == pairwise.size());
    for (std::size_t i = 0; i < a.size(); ++i) CHECK(a[i] == pairwise[i]);
  }
  SUBCASE("gravity and mass-proportional drag: -gamma v_i on everyone") {
    ExternalForces f;
    f.gravity = g;
    f.drag = Drag{0.4, 0, {}};
    accelerations(s, f, a, 1);
    const auto expected = expected_accelerations(s, g, std::vector<double>(4, 0.4));
    for (std::size_t i = 0; i < a.size(); ++i) CHECK((a[i] - expected[i]).norm() < 1e-13);
  }
  SUBCASE("drag b on listed particles: -(b / m_i) v_i on those only") {
    ExternalForces f;
    f.gravity = g;
    f.drag = Drag{0, 0.6, {0, 3}};
    accelerations(s, f, a, 1);
    const auto expected =
        expected_accelerations(s, g, {0.6 / s.particles[0].m, 0, 0, 0.6 / s.particles[3].m});
    for (std::size_t i = 0; i < a.size(); ++i) CHECK((a[i] - expected[i]).norm() < 1e-13);
  }
}

TEST_CASE("ForcedFlow without drag: the undamped flow about the CM and free fall for the CM") {
  const double t = 1.7;
  struct Case {
    double k;
    double xc, xs, vc, vs;  // x(t) = xc x0 + xs u0, u(t) = vc x0 + vs u0 for x'' = -k x
  };
  const double w = std::sqrt(2.0), W = std::sqrt(0.7);
  const Case cases[] = {
      {2.0, std::cos(w * t), std::sin(w * t) / w, -w * std::sin(w * t), std::cos(w * t)},
      {-0.7, std::cosh(W * t), std::sinh(W * t) / W, W * std::sinh(W * t), std::cosh(W * t)},
      {0.0, 1, t, 0, 1}};
  for (const Case& c : cases) {
    CAPTURE(c.k);
    const ForcedFlow m = ForcedFlow::over(c.k, 0.0, t);
    CHECK(m.xc == Approx(c.xc).epsilon(1e-14));
    CHECK(m.xs == Approx(c.xs).epsilon(1e-14));
    CHECK(m.vc == Approx(c.vc).epsilon(1e-14));
    CHECK(m.vs == Approx(c.vs).epsilon(1e-14));
    // Free fall: R = R0 + V0 t + g t^2 / 2, V = V0 + g t.
    CHECK(m.cm_v == Approx(t).epsilon(1e-15));
    CHECK(m.cm_g == Approx(t * t / 2).epsilon(1e-15));
    CHECK(m.cm_vv == 1);
    CHECK(m.cm_vg == Approx(t).epsilon(1e-15));
  }
}

TEST_CASE("ForcedFlow with drag: the textbook damped oscillator in every regime") {
  struct Case {
    const char* regime;
    double k, gamma;
  };
  // k - gamma^2 / 4 picks the regime; the critical case is exact in binary (1 - 1 = 0).
  const Case cases[] = {{"under-damped", 2, 1},
                        {"critically damped", 1, 2},
                        {"over-damped", 1, 5},
                        {"damped runaway, k < 0", -0.5, 1},
                        {"free particles, k = 0", 0, 0.7}};
  for (const Case& c : cases) {
    CAPTURE(c.regime);
    for (double t : {1e-3, 0.37, 2.5}) {
      CAPTURE(t);
      const ForcedFlow m = ForcedFlow::over(c.k, c.gamma, t);
      // Columns of the map: the solution from (x0, u0) = (1, 0) and from (0, 1).
      const auto from_x = damped(c.k, c.gamma, 1, 0, t), from_u = damped(c.k, c.gamma, 0, 1, t);
      const double scale = std::max({1.0, std::abs(from_x.first), std::abs(from_x.second)});
      CHECK(std::abs(m.xc - from_x.first) < 1e-13 * scale);
      CHECK(std::abs(m.vc - from_x.second) < 1e-13 * scale);
      CHECK(std::abs(m.xs - from_u.first) < 1e-13 * scale);
      CHECK(std::abs(m.vs - from_u.second) < 1e-13 * scale);
      // Liouville: the drag shrinks phase-space area as exp(-gamma t), whatever k.
      CHECK(m.xc * m.vs - m.xs * m.vc == Approx(std::exp(-c.gamma * t)).epsilon(1e-12));
      // The CM: V' = g - gamma V.
      CHECK(m.cm_vv == Approx(std::exp(-c.gamma * t)).epsilon(1e-15));
      CHECK(m.cm_v == Approx(double(decay_integral(c.gamma, t))).epsilon(1e-15));
      CHECK(m.cm_vg == Approx(double(decay_integral(c.gamma, t))).epsilon(1e-15));
      CHECK(m.cm_g == Approx(free_fall_per_g(c.gamma, t)).epsilon(1e-13));
    }
  }
}

TEST_CASE("ForcedFlow: the CM's fall under drag stays accurate as gamma t -> 0") {
  // (t - (1 - e^{-gamma t}) / gamma) / gamma cancels catastrophically for small gamma t; the
  // map must still give t^2 / 2 (1 - gamma t / 3 + ...) to full precision, on both sides of
  // wherever the code switches between forms.
  const double t = 2.0;
  for (double x : {1e-15, 1e-12, 1e-8, 1e-5, 1e-3, 0.0099, 0.0101, 0.05, 0.0999, 0.1, 0.1001, 0.3,
                   1.0, 10.0, 40.0}) {
    CAPTURE(x);
    const double gamma = x / t;
    const ForcedFlow m = ForcedFlow::over(1.0, gamma, t);
    CHECK(m.cm_g == Approx(free_fall_per_g(gamma, t)).epsilon(1e-13));
    // Bounds from the alternating series (decreasing terms below gamma t = 1): the sum lies
    // between its partial sums t^2 (1/2 - x/6) and t^2 (1/2 - x/6 + x^2/24).
    if (x < 1) {
      CHECK(m.cm_g >= t * t * (0.5 - x / 6) * (1 - 1e-15));
      CHECK(m.cm_g <= t * t * (0.5 - x / 6 + x * x / 24) * (1 + 1e-15));
    }
    // For large gamma t the CM has reached its terminal speed g / gamma long ago: the fall is
    // (t - 1 / gamma) / gamma.
    if (x >= 40) CHECK(m.cm_g == Approx((t - 1 / gamma) / gamma).epsilon(1e-15));
  }
}

TEST_CASE(
    "the exact step under gravity: the CM falls as R0 + V0 t + g t^2 / 2, the rest untouched") {
  const Vec3 g(0.3, -0.2, -9.8);
  for (double J : {1.0, 0.0, -0.3}) {
    CAPTURE(J);
    const System start = swarm_of_four(J);
    System forced = start, isolated = start;
    ExternalForces f;
    f.gravity = g;
    const double dt = 1e-3;
    const int steps = 2000;
    for (int i = 0; i < steps; ++i) {
      step_analytic_forced(forced, dt, f);
      step_analytic(isolated, dt);
    }
    const double t = steps * dt;
    CHECK(forced.t == Approx(t).epsilon(1e-12));  // 2000 sums of dt
    const Vec3 R = cm_position(start) + cm_velocity(start) * t + 0.5 * g * t * t;
    const Vec3 V = cm_velocity(start) + g * t;
    CHECK(max_abs(cm_position(forced) - R) < 1e-11 * std::max(1.0, R.norm()));
    CHECK(max_abs(cm_velocity(forced) - V) < 1e-11 * std::max(1.0, V.norm()));
    // The pair force is internal and gravity pulls every particle alike, so the motion about
    // the CM is the isolated swarm's (eqs. 6 and 13).
    const Vec3 R_isolated = cm_position(isolated), V_isolated = cm_velocity(isolated);
    for (std::size_t i = 0; i < start.particles.size(); ++i) {
      const Vec3 x = forced.particles[i].r - cm_position(forced);
      const Vec3 x_isolated = isolated.particles[i].r - R_isolated;
      CHECK(max_abs(x - x_isolated) < 1e-10 * std::max(1.0, x_isolated.norm()));
      const Vec3 u = forced.particles[i].v - cm_velocity(forced);
      CHECK(max_abs(u - (isolated.particles[i].v - V_isolated)) < 1e-10 * std::max(1.0, u.norm()));
    }
    // No drag: the energy in the field's frame, E + U_g, is conserved by the exact map.
    const double E0 = total_energy(start) + gravity_potential_energy(start, g);
    const double E1 = total_energy(forced) + gravity_potential_energy(forced, g);
    CHECK(std::abs(E1 - E0) < 1e-10 * (std::abs(E0) + kinetic_energy(forced)));
  }
}

TEST_CASE("the exact step under mass-proportional drag: exp(-gamma t) for the CM velocity") {
  const double gamma = 0.4, dt = 2e-3;
  const int steps = 1000;
  const double t = steps * dt;
  for (const Vec3& g : {Vec3(0, 0, 0), Vec3(0, 0, -9.8)}) {
    CAPTURE(g.z());
    for (double J : {1.0, -0.2}) {
      CAPTURE(J);
      const System start = swarm_of_four(J);
      System s = start;
      ExternalForces f;
      f.gravity = g;
      f.drag = Drag{gamma, 0, {}};
      for (int i = 0; i < steps; ++i) step_analytic_forced(s, dt, f);
      const Vec3 R0 = cm_position(start), V0 = cm_velocity(start);
      // V' = g - gamma V: V = V0 e^{-gamma t} + g (1 - e^{-gamma t}) / gamma, and R its integral.
      const double decay = std::exp(-gamma * t), phi = (1 - decay) / gamma;
      const Vec3 V = V0 * decay + g * phi;
      const Vec3 R = R0 + V0 * phi + g * (t - phi) / gamma;
      CHECK(max_abs(cm_velocity(s) - V) < 1e-12 * std::max(1.0, V.norm()));
      CHECK(max_abs(cm_position(s) - R) < 1e-12 * std::max(1.0, R.norm()));
      // About the CM every particle is a damped oscillator, x'' = -J M x - gamma x'.
      const double k = J * total_mass(start);
      for (std::size_t i = 0; i < start.particles.size(); ++i) {
        const Vec3 expected =
            damped_position(k, gamma, start.particles[i].r - R0, start.particles[i].v - V0, t);
        const Vec3 x = s.particles[i].r - cm_position(s);
        CHECK(max_abs(x - expected) < 1e-11 * std::max(1.0, expected.norm()));
      }
    }
  }
}

TEST_CASE("step_with_forces with no external force is each method's own step, to the bit") {
  const System start = testing::random_swarm(30, 0.8, 5);
  for (const MethodInfo& info : method_table()) {
    CAPTURE(info.name);
    System with = start, plain = start;
    for (int i = 0; i < 20; ++i) {
      CHECK(step_with_forces(info.id, with, 1e-2, 1, ExternalForces{}) == 0);
      step(info.id, plain, 1e-2, 1);
    }
    CHECK(with.t == plain.t);
    for (std::size_t i = 0; i < start.particles.size(); ++i) {
      CHECK(with.particles[i].r == plain.particles[i].r);
      CHECK(with.particles[i].v == plain.particles[i].v);
    }
  }
}

TEST_CASE("step_with_forces: one step of each numerical method is its documented scheme") {
  // Three particles with the pair force, gravity and drag b on two of them: every term of
  // a = -J sum m_k (r - r_k) + g - c v is exercised. The expected steps follow integrators.h.
  System start;
  start.J = 0.8;
  start.particles = {{1.0, {0.2, -0.4, 0.1}, {0.5, 0.1, -0.3}},
                     {2.0, {-0.3, 0.5, 0.0}, {-0.2, 0.4, 0.6}},
                     {0.5, {0.6, 0.1, -0.7}, {0.1, -0.5, 0.2}}};
  ExternalForces f;
  f.gravity = Vec3(0.1, 0, -9.8);
  f.drag = Drag{0, 0.3, {0, 2}};
  const std::vector<double> c = {0.3 / 1.0, 0, 0.3 / 0.5};
  const double dt = 0.05;
  const auto a0 = expected_accelerations(start, f.gravity, c);
  auto drag_power = [&](const System& s) {
    double p = 0;
    for (std::size_t i = 0; i < s.particles.size(); ++i)
      p += c[i] * s.particles[i].m * s.particles[i].v.squaredNorm();
    return p;
  };

  std::vector<Vec3> r(3), v(3);
  Method m = Method::euler;
  SUBCASE("euler: x += v dt, then v += a(x_old, v_old) dt") {
    m = Method::euler;
    for (std::size_t i = 0; i < 3; ++i) {
      r[i] = start.particles[i].r + start.particles[i].v * dt;
      v[i] = start.particles[i].v + a0[i] * dt;
    }
  }
  SUBCASE("euler-cromer: v += a dt, then x += v_new dt") {
    m = Method::euler_cromer;
    for (std::size_t i = 0; i < 3; ++i) {
      v[i] = start.particles[i].v + a0[i] * dt;
      r[i] = start.particles[i].r + v[i] * dt;
    }
  }
  SUBCASE("verlet: kick, drift, and a closing half kick with the drag taken implicitly") {
    m = Method::verlet;
    System half = start;
    for (std::size_t i = 0; i < 3; ++i) {
      half.particles[i].v += a0[i] * (dt / 2);
      half.particles[i].r += half.particles[i].v * dt;
    }
    // v1 = v_half + dt/2 (a_pair(x1) + g - c v1), solved for v1.
    const auto a1 = expected_accelerations(half, f.gravity, {0, 0, 0});
    for (std::size_t i = 0; i < 3; ++i) {
      r[i] = half.particles[i].r;
      v[i] = (half.particles[i].v + a1[i] * (dt / 2)) / (1 + c[i] * dt / 2);
    }
  }
  SUBCASE("rk4: the classical four stages on (x, v)") {
    m = Method::rk4;
    auto shifted = [&](const std::vector<Vec3>& dr, const std::vector<Vec3>& dv, double h) {
      System s = start;
      for (std::size_t i = 0; i < 3; ++i) {
        s.particles[i].r += dr[i] * h;
        s.particles[i].v += dv[i] * h;
      }
      return s;
    };
    std::vector<Vec3> v1(3);
    for (std::size_t i = 0; i < 3; ++i) v1[i] = start.particles[i].v;
    const System s2 = shifted(v1, a0, dt / 2);
    const auto a2 = expected_accelerations(s2, f.gravity, c);
    std::vector<Vec3> v2(3), v3(3), v4(3);
    for (std::size_t i = 0; i < 3; ++i) v2[i] = s2.particles[i].v;
    const System s3 = shifted(v2, a2, dt / 2);
    const auto a3 = expected_accelerations(s3, f.gravity, c);
    for (std::size_t i = 0; i < 3; ++i) v3[i] = s3.particles[i].v;
    const System s4 = shifted(v3, a3, dt);
    const auto a4 = expected_accelerations(s4, f.gravity, c);
    for (std::size_t i = 0; i < 3; ++i) {
      v4[i] = s4.particles[i].v;
      r[i] = start.particles[i].r + dt / 6 * (v1[i] + 2 * v2[i] + 2 * v3[i] + v4[i]);
      v[i] = start.particles[i].v + dt / 6 * (a0[i] + 2 * a2[i] + 2 * a3[i] + a4[i]);
    }
  }

  CAPTURE(name_of(m));
  System s = start;
  const double loss = step_with_forces(m, s, dt, 1, f);
  CHECK(s.t == Approx(dt));
  for (std::size_t i = 0; i < 3; ++i) {
    CHECK(max_abs(s.particles[i].r - r[i]) < 1e-14);
    CHECK(max_abs(s.particles[i].v - v[i]) < 1e-14);
  }
  // The drag's energy: the trapezoidal rule on its power sum c_i m_i |v_i|^2.
  CHECK(loss > 0);
  CHECK(loss == Approx(0.5 * dt * (drag_power(start) + drag_power(s))).epsilon(1e-13));
}

TEST_CASE("step_with_forces: rk4 on v' = g - gamma v is the exact solution's Taylor polynomial") {
  // With J = 0 each particle obeys the linear v' = g - gamma v, on which RK4 reproduces the
  // exact flow's expansion to order (gamma dt)^4, with v_inf = g / gamma:
  //   v1 = v_inf + (v0 - v_inf) (1 - z + z^2/2 - z^3/6 + z^4/24),  z = gamma dt,
  //   x1 = x0 + v_inf dt + (v0 - v_inf) dt (1 - z/2 + z^2/6 - z^3/24).
  System start;
  start.J = 0;
  start.particles = {{1.0, {0, 0, 1}, {1, -2, 3}}, {3.0, {1, 2, 3}, {0, 0.5, -1}}};
  const double gamma = 2.0, dt = 0.1, z = gamma * dt;
  ExternalForces f;
  f.gravity = Vec3(0, 1, -9.8);
  f.drag = Drag{gamma, 0, {}};
  System s = start;
  step_with_forces(Method::rk4, s, dt, 1, f);
  const Vec3 v_inf = f.gravity / gamma;
  for (std::size_t i = 0; i < 2; ++i) {
    const Vec3 dv0 = start.particles[i].v - v_inf;
    const Vec3 v1 = v_inf + dv0 * (1 - z + z * z / 2 - z * z * z / 6 + z * z * z * z / 24);
    const Vec3 x1 =
        start.particles[i].r + v_inf * dt + dv0 * dt * (1 - z / 2 + z * z / 6 - z * z * z / 24);
    CHECK(max_abs(s.particles[i].v - v1) < 1e-14 * 10);
    CHECK(max_abs(s.particles[i].r - x1) < 1e-14 * 10);
  }
}

TEST_CASE("step_with_forces: every numerical method converges to the exact forced motion") {
  // Gravity and mass-proportional drag on an attractive swarm: the exact motion is the CM's
  // damped fall plus a damped oscillator about it. Halving dt divides the error by 2^order.
  const System start = swarm_of_four(0.5);
  const double gamma = 0.3, t_end = 1.3;  // not a whole period, where phase errors can cancel
  ExternalForces f;
  f.gravity = Vec3(0.2, 0, -9.8);
  f.drag = Drag{gamma, 0, {}};
  const double k = stiffness(start);
  const Vec3 R0 = cm_position(start), V0 = cm_velocity(start);
  const double phi = (1 - std::exp(-gamma * t_end)) / gamma;
  const Vec3 R = R0 + V0 * phi + f.gravity * (t_end - phi) / gamma;
  auto error_after = [&](Method m, int steps) {
    System s = start;
    for (int i = 0; i < steps; ++i) step_with_forces(m, s, t_end / steps, 1, f);
    double worst = 0;
    for (std::size_t i = 0; i < start.particles.size(); ++i) {
      const Vec3 expected = R + damped_position(k, gamma, start.particles[i].r - R0,
                                                start.particles[i].v - V0, t_end);
      worst = std::max(worst, (s.particles[i].r - expected).norm());
    }
    return worst;
  };
  struct Expect {
    Method method;
    int order, steps;
  };
  for (const Expect& e : {Expect{Method::euler, 1, 4000}, Expect{Method::euler_cromer, 1, 4000},
                          Expect{Method::verlet, 2, 400}, Expect{Method::rk4, 4, 50}}) {
    CAPTURE(name_of(e.method));
    const double coarse = error_after(e.method, e.steps), fine = error_after(e.method, 2 * e.steps);
    CHECK(std::log2(coarse / fine) == Approx(e.order).epsilon(0.1));
  }
  // The exact map, in a handful of steps.
  CHECK(error_after(Method::analytic, 7) < 1e-12);
}

TEST_CASE("step_with_forces: the exact map with drag returns exactly the energy it took") {
  SUBCASE("free particles (J = 0) under gravity: the integral of gamma sum m |v|^2") {
    // v(t) = v_inf + (v0 - v_inf) e^{-gamma t} with v_inf = g / gamma, so over dt
    // int |v|^2 = |v_inf|^2 dt + 2 v_inf.(v0 - v_inf) (1 - e^{-z}) / gamma
    //             + |v0 - v_inf|^2 (1 - e^{-2z}) / (2 gamma).
    System s;
    s.J = 0;
    s.particles = {{1.0, {0, 0, 1}, {1, -2, 3}}, {3.0, {1, 2, 3}, {0, 0.5, -1}}};
    const double gamma = 0.8, dt = 0.25, z = gamma * dt;
    ExternalForces f;
    f.gravity = Vec3(0, 1, -9.8);
    f.drag = Drag{gamma, 0, {}};
    const Vec3 v_inf = f.gravity / gamma;
    double expected = 0;
    for (const Particle& p : s.particles) {
      const Vec3 d = p.v - v_inf;
      expected += gamma * p.m *
                  (v_inf.squaredNorm() * dt + 2 * v_inf.dot(d) * (-std::expm1(-z)) / gamma +
                   d.squaredNorm() * (-std::expm1(-2 * z)) / (2 * gamma));
    }
    const double loss = step_with_forces(Method::analytic, s, dt, 1, f);
    CHECK(loss == Approx(expected).epsilon(1e-12));
  }
  SUBCASE("an attractive swarm: the drop of E + U_g, which is positive") {
    const System start = swarm_of_four(1.0);
    const Vec3 g(0, 0, -9.8);
    ExternalForces f;
    f.gravity = g;
    f.drag = Drag{0.5, 0, {}};
    System s = start;
    const double loss = step_with_forces(Method::analytic, s, 0.1, 1, f);
    const double drop = (total_energy(start) + gravity_potential_energy(start, g)) -
                        (total_energy(s) + gravity_potential_energy(s, g));
    CHECK(loss > 0);
    CHECK(loss == Approx(drop).epsilon(1e-14));
  }
  SUBCASE("gravity alone takes nothing, and E + U_g is kept") {
    const System start = swarm_of_four(1.0);
    const Vec3 g(0, 0, -9.8);
    ExternalForces f;
    f.gravity = g;
    System s = start;
    CHECK(step_with_forces(Method::analytic, s, 0.1, 1, f) == 0);
    CHECK(total_energy(s) + gravity_potential_energy(s, g) ==
          Approx(total_energy(start) + gravity_potential_energy(start, g)).epsilon(1e-13));
  }
}

TEST_CASE("step_with_forces gives the same numbers on any number of threads") {
  // 1000 particles: above the size where the pairwise sum runs on threads, and cut into ten
  // blocks of rows, so that 3, 4 and 7 threads each take them in another way.
  const System start = testing::random_swarm(1000, 0.01, 9);
  ExternalForces f;
  f.gravity = Vec3(0, 0, -1);
  f.drag = Drag{0.2, 0, {}};
  for (const MethodInfo& info : method_table()) {
    CAPTURE(info.name);
    System one = start;
    const double loss_one = step_with_forces(info.id, one, 1e-2, 1, f);
    for (const int threads : {2, 3, 4, 7}) {
      CAPTURE(threads);
      System other = start;
      CHECK(step_with_forces(info.id, other, 1e-2, threads, f) == loss_one);
      CHECK(state_hash(other) == state_hash(one));
    }
  }
}
