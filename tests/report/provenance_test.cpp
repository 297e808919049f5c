#include "report/provenance.h"

#include <doctest/doctest.h>

#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <nlohmann/json.hpp>
#include <variant>

using namespace swarmlab::report;

namespace {

/// Seconds since 1970 of "YYYY-MM-DDTHH:MM:SSZ", by the calendar (no time zone involved); -1
/// for any other text.
long long seconds_of_iso_date(const std::string& s) {
  int y, mo, d, h, mi, se;
  char z = 0;
  if (s.size() != 20 || std::sscanf(s.c_str(), "%4d-%2d-%2dT%2d:%2d:%2d%c", &y, &mo, &d, &h, &mi,
                                    &se, &z) != 7 || z != 'Z' || s[4] != '-' || s[10] != 'T')
    return -1;
  // Days from civil (Howard Hinnant's algorithm).
  y -= mo <= 2;
  const long long era = (y >= 0 ? y : y - 399) / 400;
  const long long yoe = y - era * 400;
  const long long doy = (153 * (mo + (mo > 2 ? -3 : 9)) + 2) / 5 + d - 1;
  const long long doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  const long long days = era * 146097 + doe - 719468;
  return days * 86400 + h * 3600 + mi * 60 + se;
}

}  // namespace

TEST_CASE("provenance: the build's version, the compiler, the host and the UTC date now") {
  const Provenance p = provenance_now({5});
  REQUIRE(!p.version.empty());
  // The commit is the version's start; the tree is clean exactly when no hash of changes follows.
  CHECK(p.version.rfind(p.commit, 0) == 0);
  if (p.commit != "unknown") {
    REQUIRE(p.clean.has_value());
    CHECK(*p.clean == (p.version.find("-dirty-") == std::string::npos));
  }
  CHECK(!p.compiler.empty());
  CHECK(!p.os.empty());
  CHECK(!p.machine.empty());
  const long long date = seconds_of_iso_date(p.date);
  REQUIRE(date > 0);
  CHECK(std::llabs(date - (long long)std::time(nullptr)) <= 5);
  CHECK(p.seeds.seed == std::optional<std::uint64_t>(5));
}

TEST_CASE("provenance: the hand-made date reader agrees with the calendar") {
  CHECK(seconds_of_iso_date("1970-01-01T00:00:00Z") == 0);
  CHECK(seconds_of_iso_date("2000-03-01T00:00:01Z") == 951868801);  // date -u -d ... +%s
  CHECK(seconds_of_iso_date("2026-12-07 18:00:00") == -1);
}

TEST_CASE("provenance: the seeds of a preset are its swarm's; listed particles have none") {
  swarm::Preset generated;
  std::get<swarm::SwarmSpec>(generated.particles).seed = 42;
  CHECK(seeds_of(generated).seed == std::optional<std::uint64_t>(42));
  swarm::Preset listed;
  listed.particles = std::vector<swarm::Particle>{};
  CHECK(!seeds_of(listed).seed);
}

TEST_CASE("provenance: JSON with every field, read back the same; a bad field is named") {
  const Provenance p{"abc123-dirty-0f0f0f0f", "abc123", false, "GCC 12.2.0", "Linux 6.1.0", "x86_64",
                     "2026-12-07T18:00:00Z", {std::nullopt, 11, 6}};
  const nlohmann::json j = provenance_json(p);
  CHECK(j["program"] == "swarmlab");
  CHECK(j["version"] == "abc123-dirty-0f0f0f0f");
  CHECK(j["commit"] == "abc123");
  CHECK(j["clean"] == false);
  CHECK(j["host"] == nlohmann::json{{"os", "Linux 6.1.0"}, {"machine", "x86_64"}});
  CHECK(j["seeds"] == nlohmann::json{{"base", 11}, {"runs", 6}});
  std::string error;
  const std::optional<Provenance> back = provenance_from_json(j, error);
  REQUIRE(back);
  CHECK(back->version == p.version);
  CHECK(back->clean == p.clean);
  CHECK(back->os == p.os);
  CHECK(back->machine == p.machine);
  CHECK(back->date == p.date);
  CHECK(back->seeds.base == p.seeds.base);
  CHECK(back->seeds.runs == 6);
  nlohmann::json bad = j;
  bad["host"].erase("machine");
  CHECK(!provenance_from_json(bad, error));
  CHECK(error == "provenance.host.machine: missing or not text");
  bad = j;
  bad["seeds"]["base"] = -1;
  CHECK(!provenance_from_json(bad, error));
  CHECK(error == "provenance.seeds.base: not a whole number >= 0");
  bad = j;
  bad["clean"] = "yes";
  CHECK(!provenance_from_json(bad, error));
  CHECK(error == "provenance.clean: missing or not true, false or null");
}

TEST_CASE("provenance: as text lines, one each, without control characters or commas") {
  Provenance p{"abc123", "abc123", true, "GCC\n12", "Linux", "x86_64", "2026-12-07T18:00:00Z", {5}};
  std::vector<std::string> lines = provenance_lines(p);
  REQUIRE(lines.size() == 5);
  CHECK(lines[0] == "made by swarmlab abc123 from commit abc123 with a clean tree");
  CHECK(lines[1] == "compiler: GCC\\n12");  // a line break from outside never ends the line
  CHECK(lines[2] == "host: Linux x86_64");
  CHECK(lines[3] == "date: 2026-12-07T18:00:00Z");
  CHECK(lines[4] == "seeds: 5");
  p.clean = false;
  p.seeds = {std::nullopt, 7, 3};
  lines = provenance_lines(p);
  CHECK(lines[0] == "made by swarmlab abc123 from commit abc123 with uncommitted changes");
  CHECK(lines[4] == "seeds: master seed 7 and runs 0 to 2 (run k starts from run_seed of the two)");
  p.seeds = {};
  CHECK(provenance_lines(p)[4] == "seeds: none (the particles are listed)");
}

TEST_CASE("provenance: CSV comment lines hold no separator or quote a spreadsheet would split on") {
  CHECK(csv_comment_lines({"made by swarmlab x", "date: d"}) == "# made by swarmlab x\n# date: d\n");
  CHECK(csv_comment_lines({"compiler: a,=HYPERLINK(\"http://x\");\tb"}) ==
        "# compiler: a =HYPERLINK( http://x )  b\n");
  CHECK(csv_comment_lines({}).empty());
}
