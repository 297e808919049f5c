#include "swarm/measure/state_hash.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "swarm/engine/engine.h"
#include "swarm/engine/fast_engine.h"
#include "swarm/physics/diagnostics.h"
#include "swarm/preset/initial_conditions.h"

using namespace swarm;

// The pinned hashes below were computed once by the native (glibc) build. The same suite
// compiled with Emscripten and run under node must reproduce them: that is the proof that a
// preset and a seed give the same numbers to the last bit in the desktop app, the CLI and the
// browser. A change to the physics that alters results on purpose must update them (the
// failure message prints the new value); a change that should not alter results must not.

namespace {

/// 500 particles, masses uniform in [0.5, 2], positions in the unit ball, Maxwellian
/// velocities (Box-Muller: a log and a cos per component) at T = 2, CM at rest.
System maxwellian_swarm(double J_times_M) {
  SwarmSpec spec;
  spec.count = 500;
  spec.mass_min = 0.5;
  spec.mass_max = 2.0;
  spec.velocities = SwarmSpec::Velocities::maxwell;
  spec.temperature = 2.0;
  spec.cm_at_rest = true;
  spec.seed = 20260401;
  System s = generate_swarm(spec);
  s.J = J_times_M / total_mass(s);
  return s;
}

std::string hex(std::uint64_t h) {
  char text[19];
  std::snprintf(text, sizeof text, "0x%016llx", static_cast<unsigned long long>(h));
  return text;
}

/// Runs `steps` steps of dt in the unit sphere; returns the final state and counts wall hits.
System run_in_container(const System& s, Method method, int steps, double dt, std::int64_t* hits) {
  auto engine = make_engine(s, {method, CollisionMode::paper, 1.0});
  *hits = 0;
  for (int i = 0; i < steps; ++i) *hits += engine->step(dt).hits;
  return engine->system();
}

}  // namespace

TEST_CASE("the state hash sees every bit of every particle and nothing else") {
  System s = maxwellian_swarm(1.0);
  const std::uint64_t h = state_hash(s);
  CHECK(state_hash(System(s)) == h);
  for (std::size_t i : {std::size_t(0), s.particles.size() / 2, s.particles.size() - 1}) {
    for (int d = 0; d < 3; ++d) {
      System r = s, v = s;
      r.particles[i].r[d] = std::nextafter(r.particles[i].r[d], 10.0);
      v.particles[i].v[d] = std::nextafter(v.particles[i].v[d], 10.0);
      CHECK(state_hash(r) != h);
      CHECK(state_hash(v) != h);
    }
    System m = s;
    m.particles[i].m = std::nextafter(m.particles[i].m, 10.0);
    CHECK(state_hash(m) != h);
  }
  System swapped = s;
  std::swap(swapped.particles[0], swapped.particles[1]);
  CHECK(state_hash(swapped) != h);  // order matters: particle i is particle i
  System zero = s, negative_zero = s;
  zero.particles[0].v.x() = 0.0;
  negative_zero.particles[0].v.x() = -0.0;
  CHECK(state_hash(zero) != state_hash(negative_zero));
}

TEST_CASE("a seeded Maxwellian swarm has the pinned hash (native == wasm)") {
  const System s = maxwellian_swarm(1.0);
  INFO("hash ", hex(state_hash(s)));
  CHECK(state_hash(s) == 0x7353a24eb7bf5f38ULL);
}

TEST_CASE("runs in a container end in the pinned states (native == wasm)") {
  // The fast engine (the exact flow's cos, sin, cosh, sinh and the wall hits) attractive and
  // repulsive, and RK4 with pairwise forces; each must hit the wall and keep its energy, so
  // the pinned state is a physical one.
  struct Case {
    const char* name;
    double J_times_M;
    Method method;
    int steps;
    double dt;
    std::uint64_t pinned;
  };
  const Case cases[] = {
      {"fast engine, J > 0", 1.0, Method::analytic, 4000, 1e-3, 0x3a5079347b7a16c1ULL},
      {"fast engine, J < 0", -1.0, Method::analytic, 4000, 1e-3, 0x834f0b61932a109bULL},
      {"rk4, J > 0", 1.0, Method::rk4, 400, 1e-3, 0xc590cd949982c9aeULL},
  };
  for (const Case& c : cases) {
    INFO(std::string(c.name));
    const System s = maxwellian_swarm(c.J_times_M);
    if (c.method == Method::analytic) {
      CHECK(fast_engine_stats(*make_engine(s, {c.method, CollisionMode::paper, 1.0})));
    }
    std::int64_t hits = 0;
    const System end = run_in_container(s, c.method, c.steps, c.dt, &hits);
    CHECK(hits > 100);
    CHECK(std::abs(total_energy(end) - total_energy(s)) < 1e-6 * std::abs(total_energy(s)));
    INFO("hash ", hex(state_hash(end)));
    CHECK(state_hash(end) == c.pinned);
  }
}
