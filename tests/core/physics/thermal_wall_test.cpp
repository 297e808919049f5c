// A thermal wall against the physics: re-emission follows the flux-weighted Maxwellian, a
// cold gas is brought to mean kinetic energy 3/2 Tw with Maxwellian speeds, and the heat
// booked equals the energy gained.

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "swarm/engine/engine.h"
#include "swarm/measure/speed_distribution.h"
#include "swarm/physics/diagnostics.h"
#include "swarm/physics/thermal_wall.h"
#include "swarm/preset/initial_conditions.h"
#include "test_systems.h"

using namespace swarm;

TEST_CASE("reemit_from_thermal_wall draws the flux-weighted Maxwellian, and books the heat") {
  // Independent moments of the wall distribution at Tw for mass m: <v_n^2> = 2 Tw / m
  // (Rayleigh), <v_t^2> = Tw / m per tangential component, <v_n> = sqrt(pi Tw / 2 m).
  const double Tw = 2.0, m = 0.5;
  const long n = 200000;
  double vn = 0, vn2 = 0, vt2 = 0, heat = 0, gained = 0;
  WallTally tally;
  for (long i = 0; i < n; ++i) {
    Particle p{m, {0, 0, 1}, {0.1, 0, 0.3}};
    const double before = 0.5 * m * p.v.squaredNorm();
    reemit_from_thermal_wall(p, Tw, {std::uint64_t(i / 7), std::uint64_t(i % 7)}, tally);
    gained += 0.5 * m * p.v.squaredNorm() - before;
    vn += -p.v.z();
    vn2 += p.v.z() * p.v.z();
    vt2 += 0.5 * (p.v.x() * p.v.x() + p.v.y() * p.v.y());
    CHECK_MESSAGE(p.v.z() < 0, "re-emitted into the container");
  }
  heat = tally.books.wall_heat;
  CHECK(vn / n == doctest::Approx(std::sqrt(M_PI * Tw / (2 * m))).epsilon(0.01));
  CHECK(vn2 / n == doctest::Approx(2 * Tw / m).epsilon(0.01));
  CHECK(vt2 / n == doctest::Approx(Tw / m).epsilon(0.01));
  CHECK(heat == doctest::Approx(gained).epsilon(1e-12));
  CHECK(tally.hits == n);
}

TEST_CASE("thermal_uniforms: the same key gives the same draws, and neighbouring keys differ") {
  double a[3], b[3], c[3], d[3];
  thermal_uniforms({5, 9}, a);
  thermal_uniforms({5, 9}, b);
  thermal_uniforms({5, 10}, c);
  thermal_uniforms({5, 9, 1}, d);  // another run's stream
  for (int i = 0; i < 3; ++i) {
    CHECK(a[i] == b[i]);
    CHECK(a[i] != c[i]);
    CHECK(a[i] != d[i]);
    CHECK(a[i] > 0);
    CHECK(a[i] <= 1);
  }
}

TEST_CASE("Thermal wall: a cold J = 0 gas reaches 3/2 Tw per particle with Maxwellian speeds") {
  SwarmSpec spec;
  spec.count = 500;
  spec.position_radius = 0.9;
  spec.velocities = SwarmSpec::Velocities::maxwell;
  spec.temperature = 0.05;  // twenty times colder than the wall
  spec.seed = 11;
  System s = generate_swarm(spec);
  s.J = 0;
  const double Tw = 1.0;
  EngineConfig config;
  config.container_radius = 1.0;
  config.wall_temperature = Tw;
  auto engine = make_engine(s, config);
  const double dt = 2e-3;
  double E0 = total_energy(engine->system()), heat = 0;
  // Each particle meets the wall about once per time unit once warm: 10 units to warm up,
  // then snapshots 2 units apart (a fresh set of wall hits between them).
  std::vector<double> kinetic_per_particle, pooled;
  for (long step = 1; step <= 15000; ++step) {
    heat += engine->step(dt).books.wall_heat;
    if (step >= 5000 && step % 1000 == 0) {
      const System& now = engine->system();
      kinetic_per_particle.push_back(kinetic_energy(now) / double(now.particles.size()));
      // Speeds in the lab frame: the wall holds the CM, and its velocity is ~1/sqrt(N).
      for (const Particle& p : now.particles) pooled.push_back(p.v.norm() * std::sqrt(p.m / Tw));
    }
  }
  double mean_kinetic = 0;
  for (double k : kinetic_per_particle) mean_kinetic += k / double(kinetic_per_particle.size());
  CHECK(mean_kinetic == doctest::Approx(1.5 * Tw).epsilon(0.04));
  // Goodness of fit: Kolmogorov-Smirnov against the Maxwellian at Tw at the 1 % level.
  const double n = double(pooled.size());
  const double D = maxwell_ks_distance(pooled);
  CAPTURE(n);
  CHECK(std::sqrt(n) * D < 1.63);
  // The cold start itself is far from it (the test can fail).
  CHECK(std::sqrt(double(s.particles.size())) *
            maxwell_ks_distance(scaled_speeds(s, Tw)) > 5);
  CHECK(total_energy(engine->system()) - E0 == doctest::Approx(heat).epsilon(1e-9));
}

TEST_CASE("a thermal-wall run ends in the pinned state (native == wasm)") {
  // The re-emission's log, sin and cos are the core's own, and its draws keyed on step and
  // particle: the same bits natively and under node, on either engine.
  SwarmSpec spec;
  spec.count = 200;
  spec.position_radius = 0.9;
  spec.seed = 5;
  System s = generate_swarm(spec);
  s.J = 0.5 / 200;
  EngineConfig config;
  config.container_radius = 1.0;
  config.wall_temperature = 0.7;
  const std::uint64_t reference =
      testing::final_state_hash(*make_reference_engine(s, config), 2000, 1e-3, 50);
  const std::uint64_t fast = testing::final_state_hash(*make_engine(s, config), 2000, 1e-3, 50);
  INFO("hashes ", reference, " ", fast);
  CHECK(reference == 0x9b3f05e061f8e656ULL);
  CHECK(fast == 0xc0f4971391c981f3ULL);  // make_engine: the fast engine
}
