#include "labels/system_labels.h"

#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "files/preset_file.h"

using namespace swarmlab;

namespace {

swarm::Preset shipped(const char* file) {
  const swarm::PresetParse parsed = read_preset_file(std::string(SWARM_PRESET_DIR) + "/" + file);
  REQUIRE_MESSAGE(parsed.preset, parsed.error);
  return *parsed.preset;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace

TEST_CASE("the title says (edited) and the regime as it is now, only after an edit") {
  swarm::Preset p = shipped("fig2-attractive-expansion.json");
  CHECK(labels::title(p, false) == p.name);
  p.J = -p.J;  // the swarm made repulsive
  const std::string edited = labels::title(p, true);
  CHECK(contains(edited, p.name));
  CHECK(contains(edited, "(edited)"));
  CHECK(contains(edited, "repulsive (J < 0) in a container"));
  CHECK_FALSE(contains(edited, "attractive"));
  p.J = 0;
  p.container_radius.reset();
  CHECK(contains(labels::title(p, true), "free (J = 0), isolated"));
  p.name.clear();
  CHECK(contains(labels::title(p, false), "(unnamed preset)"));
}

TEST_CASE("the regime label follows the sign of J and the container") {
  swarm::Preset p = shipped("fig1-four-masses.json");
  CHECK(labels::regime_label(p) == "attractive (J > 0), isolated");
  p.J = -0.5;
  CHECK(labels::regime_label(p) == "repulsive (J < 0), isolated");
  p.container_radius = 3.0;
  CHECK(labels::regime_label(p) == "repulsive (J < 0) in a container");
}

TEST_CASE("the clock counts periods only for an isolated attractive system") {
  swarm::Preset p = shipped("fig1-four-masses.json");
  const double k = 4.0;  // omega = 2: the period is pi
  CHECK(labels::clock_text(p, k, M_PI) == "t = 3.142   \u03c9t/2\u03c0 = 1.000");
  CHECK(labels::clock_text(p, -4.0, 1.5) == "t = 1.500   \u03a9t = 3.000");
  CHECK(labels::clock_text(p, 0.0, 2.0) == "t = 2.000");
  // A wall holds the system: neither periods nor e-foldings describe its motion.
  p.container_radius = 2.0;
  CHECK(labels::clock_text(p, k, M_PI) == "t = 3.142");
  CHECK(labels::clock_text(p, -4.0, 5001) == "t = 5001.000");
}

TEST_CASE("a preset opened from text is edited unless it equals a shipped one") {
  const std::vector<swarm::Preset> list = {shipped("fig1-four-masses.json"),
                                           shipped("two-body-circular.json")};
  // The text a share link carries, read back.
  const swarm::PresetParse same = swarm::parse_preset(swarm::preset_to_json(list[0], -1));
  REQUIRE(same.preset);
  CHECK_FALSE(labels::differs_from_shipped(*same.preset, list));
  swarm::Preset changed = *same.preset;
  changed.J = 2;  // under the shipped name, with another J
  CHECK(labels::differs_from_shipped(changed, list));
  swarm::Preset renamed = *same.preset;
  renamed.name = "My four masses";
  CHECK(labels::differs_from_shipped(renamed, list));
}
