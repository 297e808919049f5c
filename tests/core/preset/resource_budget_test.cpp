#include "swarm/preset/resource_budget.h"

#include <doctest/doctest.h>

#include "swarm/preset/preset.h"
#include "test_systems.h"

using namespace swarm;

namespace {

/// Parses against no limit, so that the budget alone is under test.
Preset preset_of(const std::string& text) {
  ResourceLimits none;
  none.memory_bytes = none.particle_steps = none.pair_evaluations = none.pair_evaluations_per_step =
      1e300;
  const PresetParse p = parse_preset(text, none);
  INFO(p.error);
  REQUIRE(p.preset);
  return *p.preset;
}

std::string swarm_of(long count, const std::string& rest) {
  return R"({"J": 1, "particles": {"count": )" + std::to_string(count) +
         R"(, "position_radius": 1, "velocity": {"speed": 1}}, )" + rest + "}";
}

}  // namespace

TEST_CASE("the estimate counts particles, steps, samples and runs from the preset alone") {
  const Preset p = preset_of(swarm_of(1000, R"("method": "verlet", "compare": ["rk4", "analytic"],
    "dt": 0.01, "duration": 10, "sample_every": 10)"));
  const ResourceEstimate e = estimate_resources(p);
  CHECK(e.particles == 1000);
  CHECK(e.steps == 1000);
  CHECK(e.runs == 3);
  CHECK(e.samples == 102);  // t = 0, every 10 steps, the end
  CHECK(e.particle_steps == 1000.0 * 1000 * 3);
  // verlet 2 + rk4 4 + analytic 0 force evaluations over 1000 * 999 / 2 pairs a step
  CHECK(e.pair_evaluations_per_step == 6 * 499500.0);
  CHECK(e.pair_evaluations == 6 * 499500.0 * 1000);
  CHECK(e.output_bytes == 0);
  CHECK(estimate_resources(p, true).output_bytes > 0);
  // Memory grows in proportion to particles and samples.
  const ResourceEstimate twice = estimate_resources(preset_of(swarm_of(2000, R"("method": "verlet",
    "compare": ["rk4", "analytic"], "dt": 0.01, "duration": 10, "sample_every": 10)")));
  CHECK(twice.particle_bytes == doctest::Approx(2 * e.particle_bytes));
}

TEST_CASE("one sample every step of a billion is refused naming sample_every") {
  // The issue's preset: it grew by about 1.3 GB a minute until memory ran out.
  const std::string text = R"({"J":1,"particles":{"count":1,"position_radius":1,
    "velocity":{"speed":1}},"dt":1e-3,"duration":1e6,"sample_every":1})";
  const std::string error = resource_error(preset_of(text), ResourceLimits{});
  CHECK(error ==
        "sample_every: 1e+09 samples need ~240 GB of memory (limit ~12 GB); raise "
        "sample_every");
  CHECK(parse_preset(text).error == error);
  // Every 100th step fits (1e7 samples, ~1.3 GB).
  CHECK(resource_error(preset_of(swarm_of(1, R"("dt": 1e-3, "duration": 1e6,
    "sample_every": 100)")),
                       ResourceLimits{}) == "");
}

TEST_CASE("ten million particles: the CLI runs them, with RESULT.json they are refused") {
  const Preset p = preset_of(swarm_of(10'000'000, R"("dt": 1e-3, "duration": 1)"));
  CHECK(resource_error(p, ResourceLimits{}) == "");
  CHECK(resource_error(p, ResourceLimits{}, true) ==
        "particles.count: 1e+07 particles need ~16.6 GB of memory (limit ~12 GB), "
        "RESULT.json included; use fewer particles");
  CHECK(resource_error(p, browser_limits()) ==
        "particles.count: 1e+07 particles need ~2.56 GB of memory (limit ~1 GB); use fewer "
        "particles");
}

TEST_CASE("work beyond the limit is refused naming the run's length") {
  // 1e7 particles for 1e9 steps: 1e16 particle-steps, months of work.
  const Preset p = preset_of(swarm_of(10'000'000, R"("dt": 1e-3, "duration": 1e6,
    "sample_every": 1000000)"));
  CHECK(resource_error(p, ResourceLimits{}) ==
        "duration: 1e+07 particles x 1e+09 steps = 1e+16 particle-steps (limit 4e+12); shorten "
        "the run, raise dt or use fewer particles");
  // rk4 evaluates the forces 4 times a step: 1e4 steps x 4 x 2e4 * (2e4 - 1) / 2 pairs.
  const Preset pairs = preset_of(swarm_of(20'000, R"("method": "rk4", "dt": 1e-3,
    "duration": 10)"));
  CHECK(resource_error(pairs, ResourceLimits{}) ==
        "duration: 1e+04 steps of 2e+04 particles with the pairwise methods need 8e+12 pair "
        "forces (limit 4e+12); shorten the run, raise dt or use fewer particles");
  // In the browser one such step (8e8 pair forces) is already too long.
  CHECK(
      resource_error(pairs, browser_limits())
          .rfind(
              "particles.count: 2e+04 particles with the pairwise methods need 8e+08 pair forces a "
              "step (limit 5e+07)",
              0) == 0);
}

TEST_CASE("every shipped preset fits within the browser's limits") {
  int count = 0;
  // Named, not structured bindings: CAPTURE keeps them in a lambda, which C++17 forbids for those.
  for (const auto& shipped : swarm::testing::shipped_preset_texts()) {
    const std::string& file = shipped.first;
    const std::string& text = shipped.second;
    CAPTURE(file);
    const PresetParse p = parse_preset(text, browser_limits());
    CHECK(p.error == "");
    if (p.preset) CHECK(resource_error(*p.preset, ResourceLimits{}, true) == "");
    ++count;
  }
  CHECK(count >= 6);
}
