#include "scenarios/workloads.h"

#include <doctest/doctest.h>

#include <fstream>
#include <sstream>

using namespace swarm;

TEST_CASE("the benchmarks' built-in workloads are the shipped expansion presets") {
  // Otherwise every published benchmark number would measure a different run.
  for (bool repulsive : {false, true}) {
    const std::string path =
        std::string(SWARM_PRESET_DIR) +
        (repulsive ? "/fig3-repulsive-fireball.json" : "/fig2-attractive-expansion.json");
    CAPTURE(path);
    std::ifstream in(path);
    REQUIRE(in);
    std::stringstream text;
    text << in.rdbuf();
    const PresetParse shipped = parse_preset(text.str());
    REQUIRE_MESSAGE(shipped.preset, shipped.error);
    Preset built = swarmlab::scenarios::expansion_preset(repulsive, 4000);
    built.name = shipped.preset->name;
    built.description = shipped.preset->description;
    CHECK(preset_to_json(built) == preset_to_json(*shipped.preset));
  }
}
