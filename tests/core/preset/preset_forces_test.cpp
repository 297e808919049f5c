// The preset keys of Appendix B's gravity, floor and drag: parsed, written back, refused with
// one message naming the field and the rule, and costed.
#include <doctest/doctest.h>

#include <string>

#include "swarm/preset/preset.h"
#include "swarm/preset/resource_budget.h"

using namespace swarm;

namespace {

const std::string kTwo =
    R"("particles": [{"m": 1, "r": [0, 0, 1], "v": [1, 0, 0]}, {"m": 2, "r": [0, 0.5, 2], "v": [0, 0, 0]}],)";

std::string preset(const std::string& extra, const std::string& method = "analytic") {
  return R"({"J": 1, )" + kTwo + R"( "dt": 0.01, "duration": 1, "method": ")" + method + "\"" +
         (extra.empty() ? "" : ", " + extra) + "}";
}

std::string error_with(const std::string& extra, const std::string& method = "analytic") {
  return parse_preset(preset(extra, method)).error;
}

}  // namespace

TEST_CASE("gravity, floor and drag parse into the plan and round-trip through JSON") {
  const PresetParse a = parse_preset(preset(
      R"("gravity": [0, 0, -9.8], "floor": {"z": -0.5, "restitution": 0.9}, "drag": {"gamma": 0.2})"));
  REQUIRE(a.error == "");
  const RunPlan plan = run_plan(*a.preset);
  CHECK(plan.engine.forces.gravity == Vec3(0, 0, -9.8));
  REQUIRE(plan.engine.floor.has_value());
  CHECK(plan.engine.floor->z == -0.5);
  CHECK(plan.engine.floor->restitution == 0.9);
  REQUIRE(plan.engine.forces.drag.has_value());
  CHECK(plan.engine.forces.drag->gamma == 0.2);
  const PresetParse again = parse_preset(preset_to_json(*a.preset));
  REQUIRE(again.error == "");
  CHECK(preset_to_json(*again.preset) == preset_to_json(*a.preset));

  const PresetParse b = parse_preset(preset(R"("drag": {"b": 0.5, "particles": [1]})", "rk4"));
  REQUIRE(b.error == "");
  CHECK(run_plan(*b.preset).engine.forces.drag->particles == std::vector<std::size_t>{1});
  CHECK(preset_to_json(*parse_preset(preset_to_json(*b.preset)).preset) ==
        preset_to_json(*b.preset));
  // The floor's restitution defaults to 1 (elastic).
  CHECK(parse_preset(preset(R"("floor": {"z": 0})")).preset->floor->restitution == 1);
}

TEST_CASE("a preset without the keys writes none of them") {
  const std::string json = preset_to_json(*parse_preset(preset("")).preset);
  CHECK(json.find("gravity") == std::string::npos);
  CHECK(json.find("floor") == std::string::npos);
  CHECK(json.find("drag") == std::string::npos);
}

TEST_CASE("bad gravity, floor and drag keys get one message naming the field and the rule") {
  CHECK(error_with(R"("gravity": [0, -9.8])") == "gravity: must be an array of 3 numbers [x, y, z]");
  CHECK(error_with(R"("gravity": [0, 0, "down"])") == "gravity[2]: must be a number");
  CHECK(error_with(R"("gravity": [0, 0, 1e200])").rfind("gravity: |g| duration^2 / 2", 0) == 0);
  CHECK(error_with(R"("floor": {"z": 0, "restitution": 1.5})") ==
        "floor.restitution: must be in [0, 1] (1: elastic, 0: the particle stops falling)");
  CHECK(error_with(R"("floor": {"restitution": 1})") == "floor.z: missing (a number is required)");
  CHECK(error_with(R"("floor": {"z": 0, "height": 1})").rfind("floor.height: unknown key", 0) == 0);
  CHECK(error_with(R"("floor": {"z": 1.5})") ==
        "particles[0].r: starts below the floor (z = 1 < floor.z = 1.5)");
  CHECK(error_with(R"("container": {"radius": 3}, "floor": {"z": -3})") ==
        "floor.z: must lie inside the container, -radius < z < radius (got z = -3, "
        "container.radius = 3)");
  CHECK(error_with(R"("drag": {"gamma": 1, "b": 1})").rfind("drag: give exactly one of", 0) == 0);
  CHECK(error_with(R"("drag": {})").rfind("drag: give exactly one of", 0) == 0);
  CHECK(error_with(R"("drag": {"gamma": -1})") == "drag.gamma: must be > 0");
  CHECK(error_with(R"("drag": {"gamma": 1e5})").rfind("drag.gamma: gamma * dt must be <= 100", 0) == 0);
  CHECK(error_with(R"("drag": {"gamma": 1, "particles": [0]})") ==
        "drag.particles: goes with \"b\" (gamma acts on every particle)");
  CHECK(error_with(R"("drag": {"b": 1, "particles": [0]})").rfind(
            "drag.b: drag on chosen particles breaks the centre-of-mass picture", 0) == 0);
  CHECK(error_with(R"("drag": {"b": 1})", "rk4") ==
        "drag.particles: missing (the indices of the particles b acts on)");
  CHECK(error_with(R"("drag": {"b": 1, "particles": []})", "rk4") ==
        "drag.particles: must be a non-empty list of particle indices");
  CHECK(error_with(R"("drag": {"b": 1, "particles": [0, 0]})", "rk4") ==
        "drag.particles[1]: lists particle 0 twice");
  CHECK(error_with(R"("drag": {"b": 1, "particles": [-1]})", "rk4") ==
        "drag.particles[0]: must be >= 0");
  CHECK(error_with(R"("drag": {"b": 1, "particles": [1.5]})", "rk4") ==
        "drag.particles[0]: must be a particle index (0, 1, ...)");
  CHECK(error_with(R"("drag": {"b": 1, "particles": [2]})", "rk4") ==
        "drag.particles[0]: particle 2 does not exist (there are 2, numbered from 0)");
  CHECK(error_with(R"("drag": {"b": 1, "particles": [0]}, "compare": ["analytic"])", "rk4")
            .rfind("compare[0]: \"analytic\" cannot run drag.b", 0) == 0);
  // A generated swarm must start above the floor.
  CHECK(parse_preset(R"({"J": 1, "particles": {"count": 10, "position_radius": 1, "velocity": {"speed": 1}},
      "dt": 0.01, "duration": 1, "floor": {"z": -0.5}})")
            .error ==
        "floor.z: must be <= -particles.position_radius (the swarm is generated in a ball about "
        "the origin and must start above the floor)");
}

TEST_CASE("gravity, drag and an elastic floor cost the analytic method 15 plain fast-engine particle-steps; an inelastic floor the reference engine's 50") {
  const Preset plain = *parse_preset(preset("")).preset;
  const Preset falling = *parse_preset(preset(R"("gravity": [0, 0, -1])")).preset;
  CHECK(estimate_resources(falling).particle_steps == 15 * estimate_resources(plain).particle_steps);
  const Preset resting =
      *parse_preset(preset(R"("gravity": [0, 0, -1], "floor": {"z": -2, "restitution": 0.5})")).preset;
  CHECK(estimate_resources(resting).particle_steps == 50 * estimate_resources(plain).particle_steps);
  const std::string big = R"({"J": 1, "particles": {"count": 100000, "position_radius": 1,
      "velocity": {"speed": 1}}, "dt": 0.001, "duration": 1000, "gravity": [0, 0, -1],
      "floor": {"z": -2, "restitution": 0.5}})";
  CHECK(parse_preset(big).error.find("(x50: an inelastic floor: the reference engine") !=
        std::string::npos);
}
