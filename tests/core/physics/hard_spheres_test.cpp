// Hard spheres against the physics: contacts conserve energy and momentum, a single-speed
// gas becomes Maxwellian, the wall pressure follows the Carnahan-Starling equation of state,
// and collisions speed up thermalisation of an attractive swarm after an expansion step.

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "swarm/engine/engine.h"
#include "swarm/measure/speed_distribution.h"
#include "swarm/measure/state_hash.h"
#include "swarm/physics/diagnostics.h"
#include "swarm/physics/hard_spheres.h"
#include "swarm/preset/initial_conditions.h"
#include "test_systems.h"

using namespace swarm;

namespace {

Vec3 momentum(const System& s) {
  Vec3 P = Vec3::Zero();
  for (const Particle& p : s.particles) P += p.m * p.v;
  return P;
}

}  // namespace

TEST_CASE("collide_spheres: an elastic contact along the line of centres") {
  Particle p{1.0, {0, 0, 0}, {1, 0, 0}};
  Particle q{3.0, {0.1, 0, 0}, {0, 0.5, 0}};
  CHECK(collide_spheres(p, q));
  // Head-on along x: 1D elastic collision, u1 = (m1 - m2) / (m1 + m2) v = -0.5, u2 = 0.5.
  CHECK(p.v.x() == doctest::Approx(-0.5));
  CHECK(q.v.x() == doctest::Approx(0.5));
  CHECK(q.v.y() == doctest::Approx(0.5));  // tangential parts untouched
  CHECK_FALSE(collide_spheres(p, q));       // now separating
}

TEST_CASE("Hard spheres: energy and momentum conserved to rounding (isolated, J > 0)") {
  SwarmSpec spec;
  spec.count = 400;
  spec.position_radius = 1;
  spec.speed = 0.5;
  spec.seed = 4;
  System s = generate_swarm(spec);
  s.J = 1.0 / 400;  // omega = 1: the swarm falls through its centre about every 3 time units
  EngineConfig with, without;
  with.sphere_radius = 0.03;
  auto a = make_engine(s, with);
  auto b = make_engine(s, without);
  const double E0 = total_energy(s);
  const Vec3 P0 = momentum(s);
  for (int i = 0; i < 3000; ++i) a->step(2e-3), b->step(2e-3);
  const double scale = std::sqrt(2 * kinetic_energy(s) * total_mass(s));
  CHECK(std::abs(total_energy(a->system()) - E0) <= 1e-11 * std::abs(E0));
  CHECK((momentum(a->system()) - P0).norm() <= 1e-12 * scale);
  // ... and there were contacts: the runs part.
  CHECK((a->system().particles[0].v - b->system().particles[0].v).norm() +
            (a->system().particles[7].v - b->system().particles[7].v).norm() >
        1e-3);
}

TEST_CASE("Hard spheres: a single-speed gas becomes Maxwellian (and without contacts stays put)") {
  double h = 0;
  const System s = testing::lattice_gas(1000, 0.95, 1.0, 21, &h);
  EngineConfig with, without;
  with.container_radius = without.container_radius = 1.0;
  with.sphere_radius = 0.035;  // packing fraction ~0.05: a mean free path ~0.2
  REQUIRE(h > 0.07);
  auto a = make_engine(s, with);
  auto b = make_engine(s, without);
  for (int i = 0; i < 3000; ++i) a->step(2e-3), b->step(2e-3);
  const double T = kinetic_temperature(s);
  CHECK(T == doctest::Approx(1.0 / 3).epsilon(0.01));
  const double n = double(s.particles.size());
  CHECK(std::sqrt(n) * maxwell_ks_distance(scaled_speeds(a->system(), T)) < 1.63);
  CHECK(std::sqrt(n) * maxwell_ks_distance(scaled_speeds(b->system(), T)) > 5);
}

TEST_CASE("Hard spheres: the wall pressure follows Carnahan-Starling at packing fractions 0.1-0.3") {
  // The equation of state ties the pressure to the density of the homogeneous gas, so the
  // density is measured where the gas is homogeneous: in the inner ball of radius (R - a) / 2,
  // averaged over time. Near a hard wall the density is not uniform (the spheres pile up at
  // contact, P = T rho(contact)), so N over the container's volume, by any choice of radius,
  // would mix in the wall layer, a fraction ~3a / R of the gas here. The pressure is the
  // impulse per time on the sphere the centres reach, area 4 pi (R - a)^2 (for point
  // particles, the ideal gas exactly). eta = rho (4/3 pi a^3).
  const long N = 1500;
  const double room = 1.0;  // R - a
  for (double eta_mean : {0.1, 0.2, 0.3}) {
    CAPTURE(eta_mean);
    const double a = room * std::cbrt(eta_mean / double(N));
    double h = 0;
    const System s = testing::lattice_gas(N, room - 0.5 * a, 1.0, 31, &h);
    REQUIRE(h > 2 * a);
    EngineConfig config;
    config.container_radius = room + a;
    config.sphere_radius = a;
    auto engine = make_engine(s, config);
    const double dt = 0.03 * a;  // a typical sphere moves 3 % of its radius in a step
    const double T = 2.0 / 3.0 * kinetic_energy(s) / double(N);
    for (long step = 0; step * dt < 0.5; ++step) engine->step(dt);  // the lattice melts
    double impulse = 0, inner = 0;
    long measured = 0, counts = 0;
    for (; measured * dt < 2.0; ++measured) {
      impulse += engine->step(dt).radial_impulse;
      if (measured % 10 != 0) continue;
      for (const Particle& p : engine->system().particles) inner += p.r.norm() < 0.5 * room;
      ++counts;
    }
    const double P = impulse / (4 * M_PI * room * room * double(measured) * dt);
    const double rho = inner / counts / (4.0 / 3.0 * M_PI * std::pow(0.5 * room, 3));
    const double eta = rho * 4.0 / 3.0 * M_PI * a * a * a;
    const double Z_cs = (1 + eta + eta * eta - eta * eta * eta) / std::pow(1 - eta, 3);
    CAPTURE(eta);
    CAPTURE(P / (rho * T));
    CAPTURE(Z_cs);
    CHECK(std::abs(P / (rho * T) / Z_cs - 1) < 0.05);
  }
}

TEST_CASE("Hard spheres: an attractive swarm thermalises faster after an expansion step") {
  // J > 0: between wall hits each particle is its own oscillator about the CM and keeps its
  // energy, so once the container is expanded beyond most orbits nothing mixes the energies
  // without contacts. Measured: how far the speeds are from the Maxwellian at the kinetic
  // temperature, some time after the step.
  double h = 0;
  const System start = testing::lattice_gas(800, 0.9, 0.8, 41, &h);
  auto after_expansion = [&](std::optional<double> a) {
    System s = start;
    s.J = 1.0 / 800;  // omega = 1
    EngineConfig config;
    config.container_radius = 1.0;
    config.sphere_radius = a;
    auto engine = make_engine(s, config);
    for (int i = 0; i < 500; ++i) engine->step(2e-3);
    engine->set_container_radius(1.5);  // the expansion step
    for (int i = 0; i < 2500; ++i) engine->step(2e-3);
    const System& now = engine->system();
    return std::sqrt(800.0) * maxwell_ks_distance(scaled_speeds(now, kinetic_temperature(now)));
  };
  const double with = after_expansion(0.03), without = after_expansion(std::nullopt);
  CAPTURE(with);
  CAPTURE(without);
  CHECK(with < 1.63);
  CHECK(without > 2 * with);
}

TEST_CASE("a hard-sphere run in a moving container ends in the pinned state (native == wasm)") {
  double h = 0;
  System s = testing::lattice_gas(300, 0.9, 1.0, 9, &h);
  s.J = 0.3 / 300;
  EngineConfig config;
  config.container_radius = 1.0;
  config.sphere_radius = 0.04;
  config.wall_moves = {{0.8, 0.2}, {1.0, 0.2}};
  auto engine = make_engine(s, config);
  std::int64_t hits = 0;
  for (int i = 0; i < 2000; ++i) hits += engine->step(1e-3).hits;
  CHECK(hits > 50);
  const std::uint64_t hash = state_hash(engine->system());
  INFO("hash ", hash);
  CHECK(hash == 0x20a06b8948153f61ULL);
}
