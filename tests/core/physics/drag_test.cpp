#include <doctest/doctest.h>

#include <cmath>

#include "swarm/engine/engine.h"
#include "swarm/engine/fast_engine.h"
#include "swarm/methods/external_forces.h"
#include "swarm/physics/diagnostics.h"
#include "swarm/physics/drag.h"
#include "test_systems.h"

using namespace swarm;

namespace {

/// Four particles of total mass M = 2 with three-dimensional motion about their CM.
System quartet(double J) {
  System s;
  s.J = J;
  s.particles = {{0.25, {0.5, -1, 0.2}, {0.3, 0.1, 0.2}},
                 {0.5, {1, 0, 0}, {-0.2, 0.4, 0.7}},
                 {0.75, {-0.4, 0.3, 0}, {0.1, -0.3, -0.1}},
                 {0.5, {-1, 0.4, 0.5}, {0.6, 0.1, 0.05}}};
  return s;
}

/// The textbook solution of x'' = -k x - gamma x' for x(0) = x0, x'(0) = u0, by the roots of
/// lambda^2 + gamma lambda + k = 0 (written out per regime, with std:: functions only).
Vec3 damped_oscillator(double k, double gamma, const Vec3& x0, const Vec3& u0, double t) {
  const double h = gamma / 2, D = h * h - k;
  if (D > 0) {  // two real roots: over-damped, or a damped runaway when k < 0
    const double l1 = -h + std::sqrt(D), l2 = -h - std::sqrt(D);
    const Vec3 A = (u0 - l2 * x0) / (l1 - l2);
    return A * std::exp(l1 * t) + (x0 - A) * std::exp(l2 * t);
  }
  if (D == 0) return (x0 + (u0 + h * x0) * t) * std::exp(-h * t);
  const double w = std::sqrt(-D);
  return std::exp(-h * t) * (x0 * std::cos(w * t) + (u0 + h * x0) / w * std::sin(w * t));
}

/// The CM under gravity g and drag gamma: V' = g - gamma V.
Vec3 cm_under_drag(const Vec3& R0, const Vec3& V0, const Vec3& g, double gamma, double t) {
  const double decay = 1 - std::exp(-gamma * t);
  return R0 + (V0 - g / gamma) * decay / gamma + g * t / gamma;
}

}  // namespace

TEST_CASE("drag rates: gamma on everyone, b / m_i on the listed particles only") {
  System s = quartet(1);
  Drag gamma;
  gamma.gamma = 0.3;
  for (double c : drag_rates(gamma, s)) CHECK(c == 0.3);
  Drag b;
  b.b = 0.6;
  b.particles = {1, 2};
  const auto c = drag_rates(b, s);
  CHECK(c[0] == 0);
  CHECK(c[1] == doctest::Approx(0.6 / 0.5));
  CHECK(c[2] == doctest::Approx(0.6 / 0.75));
  CHECK(c[3] == 0);
  // Power: sum b |v_i|^2 over the listed particles.
  CHECK(drag_power(c, s) == doctest::Approx(0.6 * (s.particles[1].v.squaredNorm() +
                                                   s.particles[2].v.squaredNorm())));
}

TEST_CASE("mass-proportional drag: the closed-form damped solution in every regime, to 1e-9") {
  const Vec3 g(0, 0.5, -2);
  struct Case {
    const char* regime;
    double J, gamma;
  };
  // M = 2: k = J M. Critical: gamma = 2 sqrt(k).
  const Case cases[] = {{"under-damped", 1, 1},
                        {"critically damped", 1, 2 * std::sqrt(2.0)},
                        {"over-damped", 1, 5},
                        {"damped runaway, J < 0", -1, 1},
                        {"free particles, J = 0", 0, 0.7}};
  for (const Case& c : cases) {
    CAPTURE(c.regime);
    const System s = quartet(c.J);
    const double k = stiffness(s);
    EngineConfig config;
    config.forces.gravity = g;
    config.forces.drag = Drag{c.gamma, 0, {}};
    CHECK(fast_engine_applies(config));  // isolated, the fast engine is the closed form itself
    auto engine = make_engine(s, config);
    const double dt = 2e-3;
    double loss = 0, quadrature = 0;
    std::vector<double> rates = drag_rates(*config.forces.drag, s);
    double power = drag_power(rates, engine->system());
    for (int i = 0; i < 1500; ++i) {
      loss += engine->step(dt).books.drag_loss;
      const double next = drag_power(rates, engine->system());
      quadrature += 0.5 * dt * (power + next);
      power = next;
    }
    const double t = engine->time();
    const Vec3 R0 = cm_position(s), V0 = cm_velocity(s);
    const Vec3 R = cm_under_drag(R0, V0, g, c.gamma, t);
    double worst = 0;
    for (std::size_t i = 0; i < s.particles.size(); ++i) {
      const Vec3 x0 = s.particles[i].r - R0, u0 = s.particles[i].v - V0;
      const Vec3 expected = R + damped_oscillator(k, c.gamma, x0, u0, t);
      worst = std::max(worst, (engine->system().particles[i].r - expected).norm() /
                                  std::max(1.0, expected.norm()));
    }
    CHECK(worst < 1e-9);
    // The books' drag loss (the exact map's energy drop) equals the integral of
    // sum gamma m v^2 (trapezoidal rule on dt = 2e-3: its own error ~1e-6).
    CHECK(loss > 0);
    CHECK(loss == doctest::Approx(quadrature).epsilon(1e-5));
  }
}

TEST_CASE("drag on one particle (RK4, J = 0): v0 exp(-b t / m) while the others fly freely") {
  System s;
  s.J = 0;
  s.particles = {{1.0, {0, 0, 0}, {1, 0, 0}}, {2.0, {1, 1, 0}, {0.5, -1, 2}}, {0.5, {0, 2, 1}, {0, 0, -1}}};
  const double b = 0.5;
  EngineConfig config;
  config.method = Method::rk4;
  config.forces.drag = Drag{0, b, {1}};
  auto engine = make_engine(s, config);
  double loss = 0;
  for (int i = 0; i < 3000; ++i) loss += engine->step(1e-3).books.drag_loss;
  const double t = engine->time();
  const Particle& dragged = engine->system().particles[1];
  const Particle& start = s.particles[1];
  const double decay = std::exp(-b * t / start.m);
  CHECK((dragged.v - start.v * decay).norm() < 1e-9 * start.v.norm());
  CHECK((dragged.r - (start.r + start.v * start.m / b * (1 - decay))).norm() < 1e-9);
  for (std::size_t i : {0, 2}) {
    const Particle& p = engine->system().particles[i];
    CHECK((p.r - (s.particles[i].r + s.particles[i].v * t)).norm() < 1e-12);
    CHECK((p.v - s.particles[i].v).norm() < 1e-15);
  }
  // The energy lost: the integral of b v^2 = m v0^2 / 2 (1 - exp(-2 b t / m)), and the drop
  // of the kinetic energy.
  const double expected = 0.5 * start.m * start.v.squaredNorm() * (1 - decay * decay);
  CHECK(loss == doctest::Approx(expected).epsilon(1e-7));
  CHECK(kinetic_energy(s) - kinetic_energy(engine->system()) == doctest::Approx(expected).epsilon(1e-9));
}

TEST_CASE("Verlet with drag stays second order (the closing half kick is implicit)") {
  // One particle, J = 0, drag b: v = v0 exp(-b t / m). Halving dt must quarter the error.
  auto error = [](double dt) {
    System s;
    s.J = 0;
    s.particles = {{1.0, {0, 0, 0}, {1, 0, 0}}};
    EngineConfig config;
    config.method = Method::verlet;
    config.forces.drag = Drag{0, 2.0, {0}};
    auto engine = make_engine(s, config);
    for (long i = 0; i < long(std::lround(1 / dt)); ++i) engine->step(dt);
    return std::abs(engine->system().particles[0].v.x() - std::exp(-2.0));
  };
  const double ratio = error(1e-2) / error(5e-3);
  CHECK(ratio == doctest::Approx(4).epsilon(0.05));
}
