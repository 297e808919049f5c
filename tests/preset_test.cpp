#include "swarm/preset.h"

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "swarm/diagnostics.h"

using namespace swarm;

namespace {

const char* kGood = R"({
  "version": 1, "name": "t", "J": 1.0,
  "particles": [{"m": 1.0, "r": [0.1, 0, 0], "v": [0, 0.2, 0]},
                {"m": 2.0, "r": [-0.05, 0, 0], "v": [0, -0.1, 0]}],
  "container": {"radius": 1.0}, "method": "verlet", "dt": 0.01, "duration": 1.0
})";

/// A small valid preset with one top-level key set (or added) to a value given as JSON text.
std::string with(const std::string& key, const std::string& value) {
  // ordered_json keeps the keys in the order written, so an added key comes last.
  nlohmann::ordered_json preset = nlohmann::ordered_json::parse(R"({"J": 1.0,
    "particles": [{"m": 1.0, "r": [0.1, 0, 0], "v": [0, 0, 0]}],
    "container": {"radius": 1.0}, "dt": 0.01, "duration": 1.0})");
  preset[key] = nlohmann::ordered_json::parse(value);
  return preset.dump();
}

std::string error_of(const std::string& text) {
  const PresetParse p = parse_preset(text);
  CHECK_FALSE(p.preset.has_value());
  return p.error;
}

}  // namespace

TEST_CASE("a preset survives a round trip through JSON") {
  const PresetParse a = parse_preset(kGood);
  REQUIRE(a.preset);
  const PresetParse b = parse_preset(preset_to_json(*a.preset));
  REQUIRE(b.preset);
  CHECK(preset_to_json(*a.preset) == preset_to_json(*b.preset));
  CHECK(b.preset->method == Method::verlet);
  CHECK(step_count(*b.preset) == 100);
  const System s = initial_system(*b.preset);
  CHECK(s.particles.size() == 2);
  CHECK(s.particles[1].m == 2.0);
  CHECK(s.particles[0].r.x() == 0.1);

  const PresetParse g = parse_preset(R"({"J": -0.001, "particles": {"count": 50,
    "mass": {"min": 4, "max": 5}, "position_radius": 0.9, "velocity": {"temperature": 0.3},
    "seed": 99}, "container": {"radius": 1}, "dt": 0.001,
    "expansion": {"factor": 1.05, "stages": 4, "tau": 0.5}})");
  REQUIRE(g.preset);
  const PresetParse g2 = parse_preset(preset_to_json(*g.preset));
  REQUIRE(g2.preset);
  CHECK(g2.preset->expansion->thermalize_fraction == 0.8);
  CHECK(step_count(*g2.preset) == 2000);
  const System s1 = initial_system(*g.preset), s2 = initial_system(*g2.preset);
  CHECK(total_energy(s1) == total_energy(s2));
  CHECK(s1.J == -0.001);
}

TEST_CASE("every bad input gets one message naming the field and the rule") {
  struct Case {
    std::string json, message;
  };
  const Case cases[] = {
      {"{\"J\": 1,", "preset: not valid JSON"},
      {"[1, 2]", "preset: must be a JSON object"},
      {with("J", "\"strong\""), "J: must be a number"},
      // No JSON value holds 1e999, so this text is written out whole.
      {R"({"J": 1e999, "particles": [{"m": 1, "r": [0,0,0], "v": [0,0,0]}], "dt": 0.1,
           "duration": 1})",
       "preset: a number cannot be read"},
      {with("dt", "0"), "dt: must be > 0"},
      {with("dt", "-1"), "dt: must be > 0"},
      {with("duration", "0"), "duration: must be > 0"},
      {with("colour", "1"), "colour: unknown key"},
      {with("method", "\"leapfrog\""), "method: unknown method \"leapfrog\""},
      {with("collisions", "\"soft\""), "collisions: must be \"paper\" or \"exact\""},
      {with("container", "{\"radius\": 0}"), "container.radius: must be > 0"},
      {with("container", "{\"radius\": -2}"), "container.radius: must be > 0"},
      {with("container", "{\"radius\": 0.05}"), "particles[0].r: starts outside the container"},
      {with("particles", "[]"), "particles: must hold at least one particle"},
      {with("particles", "[{\"m\": 0, \"r\": [0,0,0], \"v\": [0,0,0]}]"),
       "particles[0].m: must be > 0"},
      {with("particles",
            "[{\"m\": 1, \"r\": [0,0,0], \"v\": [0,0,0]}, {\"m\": -1, \"r\": [0,0,0], \"v\": "
            "[0,0,0]}]"),
       "particles[1].m: must be > 0"},
      {with("particles", "[{\"m\": 1, \"r\": [0,0], \"v\": [0,0,0]}]"),
       "particles[0].r: must be an array of 3 numbers"},
      {with("particles", "[{\"m\": 1, \"r\": [0,0,0]}]"), "particles[0].v: missing"},
      {with("particles", "[{\"m\": 1, \"r\": [0,\"a\",0], \"v\": [0,0,0]}]"),
       "particles[0].r[1]: must be a number"},
      {with("particles", "{\"count\": 0, \"position_radius\": 1, \"velocity\": {\"speed\": 1}}"),
       "particles.count: must be between 1 and"},
      {with("particles", "{\"count\": 2.5, \"position_radius\": 1, \"velocity\": {\"speed\": 1}}"),
       "particles.count: must be a whole number"},
      {with("particles", "{\"count\": 5, \"position_radius\": 2, \"velocity\": {\"speed\": 1}}"),
       "particles.position_radius: must be <= container.radius"},
      {with("particles", "{\"count\": 5, \"position_radius\": 1, \"velocity\": {}}"),
       "particles.velocity: give exactly one of"},
      {with("particles",
            "{\"count\": 5, \"mass\": {\"min\": 5, \"max\": 4}, \"position_radius\": 1, "
            "\"velocity\": {\"speed\": 1}}"),
       "particles.mass.max: must be >= particles.mass.min"},
      {with("particles", "7"), "particles: must be a list of particles or a generator object"},
      {with("expansion", "{\"factor\": 0.5, \"stages\": 3, \"tau\": 1}"), "duration: leave it out"},
      {R"({"J": 1, "particles": [{"m": 1, "r": [0,0,0], "v": [0,0,0]}], "dt": 0.1,
           "expansion": {"factor": 1.1, "stages": 3, "tau": 1}})",
       "expansion: needs a container"},
      {R"({"J": 1, "particles": [{"m": 1, "r": [0,0,0], "v": [0,0,0]}], "dt": 0.1,
           "container": {"radius": 1}, "expansion": {"factor": 0.5, "stages": 3, "tau": 1}})",
       "expansion.factor: must be >= 1"},
      {R"({"J": 1, "particles": [{"m": 1, "r": [0,0,0], "v": [0,0,0]}], "dt": 0.1,
           "container": {"radius": 1}, "expansion": {"factor": 2, "stages": 3, "tau": 1,
           "thermalize": 1}})",
       "expansion.thermalize: must be in [0, 1)"},
      {with("duration", "1e12"), "duration: must give between 1 and 1e9 steps"},
      {with("version", "2"), "version: must be 1"},
      {R"({"method": "euler", "collisions": "exact", "J": 1, "dt": 0.1, "duration": 1,
           "particles": [{"m": 1, "r": [0,0,0], "v": [0,0,0]}], "container": {"radius": 1}})",
       "collisions: \"exact\" needs method \"analytic\""},
      {R"({"J": -5, "particles": [{"m": 1, "r": [0,0,0], "v": [0,0,0]},
           {"m": 1, "r": [1,0,0], "v": [0,0,0]}], "dt": 0.01, "duration": 1000})",
       "duration: an isolated repulsive system grows as exp(Omega t)"},
      {R"({"particles": [{"m": 1, "r": [0,0,0], "v": [0,0,0]}], "dt": 0.1, "duration": 1})",
       "J: missing"},
      {R"({"J": 1, "dt": 0.1, "duration": 1})", "particles: missing"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.json);
    const std::string error = error_of(c.json);
    CHECK(error.rfind(c.message, 0) == 0);
    CHECK(error.find('\n') == std::string::npos);
  }
}

TEST_CASE("pairwise methods refuse swarms too large to integrate pair by pair") {
  const std::string big = R"({"J": 1, "method": "rk4", "particles": {"count": 50000,
    "position_radius": 1, "velocity": {"speed": 1}}, "dt": 0.01, "duration": 1})";
  CHECK(error_of(big).rfind("method: \"rk4\" sums over every pair", 0) == 0);
}

TEST_CASE("every shipped preset is valid") {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(SWARM_PRESET_DIR)) {
    if (entry.path().extension() != ".json") continue;
    std::ifstream in(entry.path());
    std::stringstream text;
    text << in.rdbuf();
    CAPTURE(entry.path().string());
    const PresetParse p = parse_preset(text.str());
    CHECK(p.error == "");
    CHECK_FALSE(p.preset->description.empty());
    ++count;
  }
  CHECK(count >= 6);
}
