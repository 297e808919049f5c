#include "swarm/preset/ensemble_seed.h"

#include <doctest/doctest.h>

#include <set>

#include "swarm/physics/diagnostics.h"

using namespace swarm;

TEST_CASE("run seeds: one per index, the same every time, within a preset's 53 bits") {
  std::set<std::uint64_t> seen;
  for (std::uint64_t k = 0; k < 1000; ++k) {
    const std::uint64_t s = run_seed(42, k);
    CHECK(s == run_seed(42, k));
    CHECK(s < (std::uint64_t(1) << 53));
    seen.insert(s);
  }
  CHECK(seen.size() == 1000);
  CHECK(run_seed(43, 0) != run_seed(42, 0));
}

TEST_CASE("with_seed: a generated swarm takes the seed; listed particles need a perturbation") {
  Preset p;
  SwarmSpec spec;
  spec.count = 50;
  p.particles = spec;
  p.container_radius = 2.0;
  const SeededPreset a = with_seed(p, 7, 0), b = with_seed(p, 8, 0);
  REQUIRE(a.preset);
  REQUIRE(b.preset);
  CHECK(std::get<SwarmSpec>(a.preset->particles).seed == 7);
  CHECK(initial_system(*a.preset).particles[0].r != initial_system(*b.preset).particles[0].r);
  // A hot wall's noise is the run's own too: its draws are keyed on the seed.
  CHECK(run_plan(*a.preset).engine.wall_stream == 7);
  CHECK(run_plan(*b.preset).engine.wall_stream == 8);

  Preset listed;
  listed.particles = std::vector<Particle>{{1, {0.5, 0, 0}, {0, 1, 0}}, {1, {-0.5, 0, 0}, {0, -1, 0}}};
  listed.container_radius = 1.0;
  const SeededPreset refused = with_seed(listed, 7, 0);
  CHECK_FALSE(refused.preset);
  CHECK(refused.error.find("particles: listed particles start every run the same") == 0);
  // Perturbed: each position moves by at most eps x the rms distance from the CM (0.5 here),
  // each velocity by at most eps x the rms speed about the CM velocity (1 here).
  const SeededPreset moved = with_seed(listed, 7, 0.01);
  REQUIRE(moved.preset);
  const auto& q = std::get<std::vector<Particle>>(moved.preset->particles);
  const auto& o = std::get<std::vector<Particle>>(listed.particles);
  for (std::size_t i = 0; i < 2; ++i) {
    CHECK((q[i].r - o[i].r).norm() <= 0.01 * 0.5);
    CHECK((q[i].v - o[i].v).norm() <= 0.01 * 1.0);
    CHECK(q[i].r != o[i].r);
  }
  CHECK(std::get<std::vector<Particle>>(with_seed(listed, 8, 0.01).preset->particles)[0].r != q[0].r);
  // Moved out of the container: the preset's own rule.
  listed.container_radius = 0.5000001;
  bool any_refused = false;
  for (std::uint64_t s = 0; s < 20; ++s) {
    const SeededPreset r = with_seed(listed, s, 0.5);
    if (!r.preset) {
      any_refused = true;
      CHECK(r.error.find("starts outside the container") != std::string::npos);
    }
  }
  CHECK(any_refused);
}
