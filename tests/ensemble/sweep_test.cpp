#include "ensemble/sweep.h"

#include <doctest/doctest.h>

#include <stdlib.h>

#include <filesystem>
#include <fstream>

using namespace swarmlab::ensemble;
namespace fs = std::filesystem;

namespace {

/// A base preset in a new folder of its own (two suites running at once never share one).
std::string base_dir() {
  std::string name = (fs::temp_directory_path() / "swarmlab-sweep-test.XXXXXX").string();
  REQUIRE(::mkdtemp(name.data()) != nullptr);
  const fs::path dir = name;
  std::ofstream(dir / "base.json")
      << R"({"J": 1, "particles": {"count": 10, "position_radius": 0.5, "velocity": {"speed": 1}},
            "container": {"radius": 1}, "dt": 0.01, "duration": 1})";
  return dir.string();
}

}  // namespace

TEST_CASE("sweep: a grid is every combination, the last key changing fastest") {
  const std::string dir = base_dir();
  const SweepRead r = read_sweep(
      R"({"preset": "base.json", "grid": {"J": [0.5, 2], "particles.count": [10, 20, 30]}, "seeds": 4})",
      dir + "/sweep.json");
  REQUIRE(r.sweep);
  REQUIRE(r.sweep->points.size() == 6);
  CHECK(r.sweep->seeds == 4);
  CHECK(r.sweep->points[0].values == R"({"J":0.5,"particles.count":10})");
  CHECK(r.sweep->points[5].values == R"({"J":2,"particles.count":30})");
  CHECK(r.sweep->points[4].preset.J == 2);
  CHECK(std::get<swarm::SwarmSpec>(r.sweep->points[4].preset.particles).count == 20);
  CHECK(is_sweep(R"({"preset": "b.json", "points": []})"));
  CHECK_FALSE(is_sweep(R"({"J": 1, "particles": []})"));
  fs::remove_all(dir);
}

TEST_CASE("sweep: each wrong key or value is one message naming it") {
  const std::string dir = base_dir(), at = dir + "/sweep.json";
  CHECK(read_sweep(R"({"preset": "base.json", "grid": {"K": [1]}})", at).error ==
        "K: not a key of the base preset (a sweep varies what the preset already sets)");
  CHECK(read_sweep(R"({"preset": "base.json", "grid": {"J": []}})", at).error ==
        "grid.J: must be a non-empty list of values");
  CHECK(read_sweep(R"({"preset": "base.json", "points": [{"dt": -1}]})", at).error ==
        R"(point {"dt":-1}: dt: must be > 0)");
  CHECK(read_sweep(R"({"preset": "nope.json", "points": [{"J": 1}]})", at).error.find("cannot open") !=
        std::string::npos);
  CHECK(read_sweep(R"({"preset": "base.json", "grid": {"J": [1]}, "points": [{"J": 1}]})", at).error ==
        "grid, points: give one of them");
  CHECK(read_sweep(R"({"preset": "base.json", "grid": {"J": [1]}, "seeds": 0})", at).error ==
        "seeds: must be a whole number from 1 to 1,000,000");
  CHECK(read_sweep(R"({"preset": "base.json", "grid": {"J": [1]}, "colour": 1})", at).error.find("colour: unknown key") == 0);
  // Control characters reach plan.json, runs.csv and the terminal: refused, named.
  CHECK(read_sweep(R"({"preset": "base.json", "points": [{"name": "a\nb"}]})", at).error ==
        "name: a value that holds a newline (byte 2)");
  CHECK(read_sweep(R"({"preset": "base.json", "points": [{"J\u0085": 1}]})", at).error ==
        "\"J\\u0085\": a key that holds a C1 control character (byte 2)");
  CHECK(read_sweep(R"({"preset": "base\r.json", "points": [{"J": 1}]})", at).error ==
        "preset: the base preset's file name holds a carriage return (byte 5)");
  fs::remove_all(dir);
}
