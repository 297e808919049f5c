// The preset keys of the Appendix B walls and contacts (core/src/preset/): read, written
// back, turned into the engine's configuration, and refused with one message when senseless.

#include <doctest/doctest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "swarm/engine/fast_engine.h"
#include "swarm/preset/preset.h"
#include "swarm/preset/resource_budget.h"

using namespace swarm;

namespace {

/// A small valid preset in a container with top-level keys set to values given as JSON text.
std::string preset_with(std::initializer_list<std::pair<const char*, const char*>> keys) {
  nlohmann::ordered_json preset = nlohmann::ordered_json::parse(R"({"J": 0,
    "particles": {"count": 50, "position_radius": 0.5, "velocity": {"temperature": 1}},
    "container": {"radius": 1.0}, "dt": 0.01, "duration": 1.0})");
  for (const auto& kv : keys) preset[kv.first] = nlohmann::ordered_json::parse(kv.second);
  return preset.dump();
}

}  // namespace

TEST_CASE("container moves, a wall temperature and hard spheres are read and written back") {
  const PresetParse a = parse_preset(preset_with(
      {{"container", R"({"radius": 1, "moves": [{"to": 0.5, "speed": 0.1}, {"to": 2, "speed": 1}]})"},
       {"hard_spheres", R"({"radius": 0.02})"}}));
  REQUIRE(a.error == "");
  REQUIRE(a.preset->wall_moves.size() == 2);
  CHECK(a.preset->wall_moves[1].to == 2);
  CHECK(a.preset->wall_moves[0].speed == 0.1);
  CHECK(*a.preset->sphere_radius == 0.02);
  const PresetParse b = parse_preset(preset_to_json(*a.preset));
  REQUIRE(b.preset);
  CHECK(preset_to_json(*b.preset) == preset_to_json(*a.preset));
  const RunPlan plan = run_plan(*b.preset);
  CHECK(plan.engine.wall_moves.size() == 2);
  CHECK(*plan.engine.sphere_radius == 0.02);
  CHECK_FALSE(fast_engine_applies(plan.engine));

  const PresetParse hot =
      parse_preset(preset_with({{"container", R"({"radius": 1, "wall_temperature": 2.5})"}}));
  REQUIRE(hot.preset);
  CHECK(*run_plan(*hot.preset).engine.wall_temperature == 2.5);
  CHECK(*parse_preset(preset_to_json(*hot.preset)).preset->wall_temperature == 2.5);
  // Features off: the configuration the fast engine has always run.
  CHECK(fast_engine_applies(run_plan(*parse_preset(preset_with({})).preset).engine));
}

TEST_CASE("senseless or out-of-range wall and sphere keys get one message naming the field") {
  struct Case {
    std::string json, message;
  };
  const Case cases[] = {
      {preset_with({{"container", R"({"radius": 1, "moves": []})"}}), "container.moves: must be a list"},
      {preset_with({{"container", R"({"radius": 1, "moves": [{"to": 0, "speed": 1}]})"}}),
       "container.moves[0].to: must be in (0, 1e100]"},
      {preset_with({{"container", R"({"radius": 1, "moves": [{"to": 0.5, "speed": -1}]})"}}),
       "container.moves[0].speed: must be in (0, 1e100]"},
      {preset_with({{"container", R"({"radius": 1, "moves": [{"to": 0.5}]})"}}),
       "container.moves[0].speed: missing"},
      {preset_with({{"container", R"({"radius": 1, "moves": [{"to": 0.5, "speed": 1, "at": 2}]})"}}),
       "container.moves[0].at: unknown key"},
      {preset_with({{"container", R"({"radius": 1, "wall_temperature": 0})"}}),
       "container.wall_temperature: must be in (0, 1e100]"},
      {preset_with({{"container", R"({"radius": 1, "wall_temperature": 1, "moves": [{"to": 0.5, "speed": 1}]})"}}),
       "container.wall_temperature: a wall either moves"},
      {preset_with({{"hard_spheres", R"({"radius": 0})"}}), "hard_spheres.radius: must be > 0"},
      {preset_with({{"hard_spheres", R"({"radius": 0.01})"}, {"floor", R"({"z": -0.9})"}}),
       "floor: hard spheres on a floor are not modelled yet"},
      {preset_with({{"hard_spheres", R"({})"}}), "hard_spheres.radius: missing"},
      {preset_with({{"hard_spheres", R"({"radius": 0.6})"}}),
       "hard_spheres.radius: must be < container.radius / 2"},
      {preset_with({{"hard_spheres", R"({"radius": 0.3})"},
                    {"particles", R"({"count": 1, "position_radius": 0.8, "velocity": {"speed": 1}})"}}),
       "particles.position_radius: must be <="},
      {preset_with({{"hard_spheres", R"({"radius": 0.2})"},
                    {"particles", R"({"count": 50, "position_radius": 0.5, "velocity": {"speed": 1}})"}}),
       "hard_spheres.radius: the spheres would fill"},
      {preset_with({{"hard_spheres", R"({"radius": 0.01})"},
                    {"container", R"({"radius": 1, "moves": [{"to": 0.015, "speed": 1}]})"}}),
       "container.moves[0].to: must be > 2 * hard_spheres.radius"},
      {preset_with({{"hard_spheres", R"({"radius": 0.01})"}, {"collisions", R"("exact")"}}),
       "collisions: \"exact\" solves contact times with a fixed elastic wall only"},
      {R"({"J": 0, "particles": [{"m": 1, "r": [0.95, 0, 0], "v": [0, 0, 0]}], "dt": 0.01,
           "duration": 1, "container": {"radius": 1}, "hard_spheres": {"radius": 0.1}})",
       "particles[0].r: a sphere's centre must start within"},
      {R"({"J": 0, "particles": [{"m": 1, "r": [0, 0, 0], "v": [0, 0, 0]}], "dt": 0.01,
           "container": {"radius": 1, "moves": [{"to": 2, "speed": 1}]},
           "expansion": {"factor": 1.1, "stages": 3, "tau": 1}})",
       "expansion: the wall already moves"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.json);
    const PresetParse p = parse_preset(c.json);
    CHECK_FALSE(p.preset.has_value());
    CAPTURE(p.error);
    CHECK(p.error.rfind(c.message, 0) == 0);
  }
}

TEST_CASE("hard spheres are costed as the reference engine's work, moving or hot walls as the fast engine's") {
  const Preset plain = *parse_preset(preset_with({})).preset;
  const Preset spheres = *parse_preset(preset_with({{"hard_spheres", R"({"radius": 0.01})"}})).preset;
  const Preset hot =
      *parse_preset(preset_with({{"container", R"({"radius": 1, "wall_temperature": 1})"}})).preset;
  const Preset moving = *parse_preset(preset_with({{"container",
                                                     R"({"radius": 1, "moves": [{"to": 0.5, "speed": 1}]})"}}))
                             .preset;
  const double base = estimate_resources(plain).particle_steps;
  CHECK(estimate_resources(spheres).particle_steps > 10 * base);
  CHECK(estimate_resources(hot).particle_steps == base);
  CHECK(estimate_resources(moving).particle_steps == base);
  CHECK(estimate_resources(spheres).particle_bytes > estimate_resources(plain).particle_bytes);
  ResourceLimits tight;
  tight.particle_steps = 2 * base;
  CHECK(resource_error(plain, tight).empty());
  CHECK(resource_error(spheres, tight).find("hard-sphere contacts") != std::string::npos);
}
