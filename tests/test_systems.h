#pragma once
// Small systems the tests share, built by hand so that expected values follow from the
// equations rather than from the code under test.

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "math/portable_math.h"
#include "swarm/engine/engine.h"
#include "swarm/measure/state_hash.h"
#include "swarm/physics/diagnostics.h"
#include "swarm/physics/system.h"
#include "swarm/preset/initial_conditions.h"
#include "swarm/preset/preset.h"

namespace swarm::testing {

/// n unit masses, all at speed `speed` in directions drawn from the generator's Maxwellian
/// (normalised), on a simple cubic lattice filling a ball of radius `room`, nearest first,
/// so that no two spheres start overlapping when the spacing exceeds 2a.
inline System lattice_gas(long n, double room, double speed, std::uint64_t seed, double* spacing) {
  SwarmSpec spec;
  spec.count = n;
  spec.velocities = SwarmSpec::Velocities::maxwell;
  spec.cm_at_rest = true;
  spec.seed = seed;
  System s = generate_swarm(spec);
  const double volume = 4.0 / 3.0 * M_PI * room * room * room;
  // The core's own cube root (exp and log), so that the start is the same bits in wasm.
  double h = portable::exp(portable::log(volume / double(n)) / 3);
  std::vector<Vec3> sites;
  while (long(sites.size()) < n) {
    sites.clear();
    const int k = int(room / h) + 1;
    for (int x = -k; x <= k; ++x)
      for (int y = -k; y <= k; ++y)
        for (int z = -k; z <= k; ++z) {
          const Vec3 r = h * Vec3(x + 0.5, y + 0.5, z + 0.5);
          if (r.norm() <= room) sites.push_back(r);
        }
    if (long(sites.size()) < n) h *= 0.98;
  }
  std::stable_sort(sites.begin(), sites.end(),
                   [](const Vec3& a, const Vec3& b) { return a.norm() < b.norm(); });
  for (long i = 0; i < n; ++i) {
    Particle& p = s.particles[std::size_t(i)];
    p.m = 1;
    p.r = sites[std::size_t(i)];
    p.v = speed * p.v.normalized();
  }
  s.J = 0;
  *spacing = h;
  return s;
}

/// The four masses of the paper's Fig. 1 (0.25, 0.5, 1, 1.5) at its drawn positions, with
/// velocities chosen by hand so the orbits are genuinely three-dimensional.
inline System four_masses(double J = 1.0) {
  System s;
  s.J = J;
  s.particles = {{0.25, {0, -1, 0}, {0.3, 0.1, 0.2}},
                 {0.5, {5, 0, 0}, {-0.2, 0.4, 0}},
                 {1.0, {4, 3, 0}, {0.1, -0.3, -0.1}},
                 {1.5, {-1, 4, 0.5}, {0, 0.1, 0.05}}};
  return s;
}

inline System random_swarm(long n, double J, std::uint64_t seed, double radius = 1.0,
                           double speed = 1.0) {
  SwarmSpec spec;
  spec.count = n;
  spec.mass_min = 4;
  spec.mass_max = 5;
  spec.position_radius = radius;
  spec.speed = speed;
  spec.seed = seed;
  System s = generate_swarm(spec);
  s.J = J;
  return s;
}

/// Masses in [4, 5], positions in the unit ball, speeds up to `speed`, J = sign / M so that
/// sqrt(|J| M) = 1: an amplitude above the unit container, so the wall is hit often.
inline System crowded_swarm(long n, double sign, std::uint64_t seed, double speed = 1.5) {
  System s = random_swarm(n, 1.0, seed, 1.0, speed);
  s.J = sign / total_mass(s);
  return s;
}

/// The largest difference in any particle's position or velocity between two states of the
/// same particles.
inline double max_state_difference(const System& a, const System& b) {
  double worst = 0;
  for (std::size_t i = 0; i < a.particles.size(); ++i) {
    worst = std::max(worst, (a.particles[i].r - b.particles[i].r).norm());
    worst = std::max(worst, (a.particles[i].v - b.particles[i].v).norm());
  }
  return worst;
}

/// The hash of the state that `engine` ends in after `steps` steps of dt, having hit the wall
/// more than min_hits times: for pinning a run's final state (native == wasm).
inline std::uint64_t final_state_hash(Engine& engine, int steps, double dt, std::int64_t min_hits) {
  std::int64_t hits = 0;
  for (int i = 0; i < steps; ++i) hits += engine.step(dt).hits;
  CHECK(hits > min_hits);
  return state_hash(engine.system());
}

/// 100,000 steps in the unit sphere, attractive and repulsive: the energy must hold to 1e-10
/// relative (in the repulsive case rounding grows as exp(Omega t) unless the engine keeps the
/// CM and the particles one), and the swarm must stay inside.
template <class MakeEngine>
void check_energy_kept_in_fixed_container(MakeEngine make_engine) {
  for (double sign : {+1.0, -1.0}) {
    CAPTURE(sign);
    const System s = crowded_swarm(200, sign, 21);
    auto engine = make_engine(s, EngineConfig{Method::analytic, CollisionMode::paper, 1.0});
    const double E0 = total_energy(s);
    std::int64_t hits = 0;
    for (int i = 0; i < 100000; ++i) hits += engine->step(1e-3).hits;
    CHECK(hits > 10000);
    CHECK(std::abs(total_energy(engine->system()) - E0) / std::abs(E0) < 1e-10);
    for (const auto& p : engine->system().particles) CHECK(p.r.norm() < 1.01);
  }
}

/// Two unit masses at x = +-1/2 on a circle about their CM at rest, J = 1: k = J M = 2, so
/// omega = sqrt(2) and the circular speed is omega / 2. Exactly, particle 0 is at
/// (cos(omega t), sin(omega t), 0) / 2.
inline System two_body_circle() {
  const double w = std::sqrt(2.0);
  System s;
  s.J = 1.0;
  s.particles = {{1.0, {0.5, 0, 0}, {0, 0.5 * w, 0}}, {1.0, {-0.5, 0, 0}, {0, -0.5 * w, 0}}};
  return s;
}

/// The shipped presets (assets/presets/*.json) as {file name, text}.
inline std::vector<std::pair<std::string, std::string>> shipped_preset_texts() {
  std::vector<std::pair<std::string, std::string>> presets;
  for (const auto& entry : std::filesystem::directory_iterator(SWARM_PRESET_DIR)) {
    if (entry.path().extension() != ".json") continue;
    std::ifstream in(entry.path());
    std::stringstream text;
    text << in.rdbuf();
    presets.emplace_back(entry.path().filename().string(), text.str());
  }
  return presets;
}

/// A shipped preset (assets/presets/NAME), parsed; the test stops if it does not validate.
inline Preset shipped_preset(const std::string& name) {
  std::ifstream in(std::string(SWARM_PRESET_DIR) + "/" + name);
  std::stringstream text;
  text << in.rdbuf();
  const PresetParse parsed = parse_preset(text.str());
  REQUIRE_MESSAGE(parsed.preset, parsed.error);
  return *parsed.preset;
}

/// Steps `engine`, started from s, 5,000 times (dt = 1e-3) and checks that the momentum the
/// wall took up is what the system lost.
inline void check_wall_takes_lost_momentum(Engine& engine, const System& s) {
  Vec3 to_wall = Vec3::Zero();
  for (int i = 0; i < 5000; ++i) to_wall += engine.step(1e-3).wall_momentum;
  const Vec3 lost = total_momentum(s) - total_momentum(engine.system());
  CHECK(to_wall.norm() > 1.0);
  CHECK((to_wall - lost).norm() < 1e-10 * to_wall.norm());
}

}  // namespace swarm::testing
