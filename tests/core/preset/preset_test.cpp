#include "swarm/preset/preset.h"

#include <doctest/doctest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "swarm/physics/diagnostics.h"
#include "swarm/run/run.h"
#include "test_systems.h"

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
       "duration: an isolated repulsive system's energies grow as exp(2 Omega t)"},
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
  // Named, not structured bindings: CAPTURE keeps them in a lambda, which C++17 forbids for those.
  for (const auto& shipped : swarm::testing::shipped_preset_texts()) {
    const std::string& file = shipped.first;
    const std::string& text = shipped.second;
    CAPTURE(file);
    const PresetParse p = parse_preset(text);
    CHECK(p.error == "");
    CHECK_FALSE(p.preset->description.empty());
    ++count;
  }
  CHECK(count >= 6);
}

namespace {

/// Two unit masses at +-0.5 at rest, isolated, with coupling J and Omega * duration = growth.
std::string pair_pushing_apart(double J, double growth) {
  const double Omega = std::sqrt(std::abs(J) * 2);
  std::ostringstream os;
  os.precision(17);
  os << R"({"J": )" << J << R"(, "particles": [{"m": 1, "r": [0.5, 0, 0], "v": [0, 0, 0]},
      {"m": 1, "r": [-0.5, 0, 0], "v": [0, 0, 0]}], "dt": 0.01, "duration": )"
     << growth / Omega << "}";
  return os.str();
}

}  // namespace

TEST_CASE("the repulsive limit is where exp(2 Omega t) times the energy scale reaches 1e300") {
  // Energies grow as exp(2 Omega t): the pair's energy scale (bounded by M (Omega C)^2 +
  // (1 + |J| M) M (2 C)^2 = 28 with C = 2 r_max = 1) reaches 1e300 at
  // Omega t = (ln 1e300 - ln 28) / 2 = 343.7; a double overflows near Omega t = 355.
  const double limit = (std::log(1e300) - std::log(28.0)) / 2;
  CHECK(parse_preset(pair_pushing_apart(-1, limit - 0.1)).preset.has_value());
  const std::string error = error_of(pair_pushing_apart(-1, limit + 0.1));
  CHECK(error.rfind("duration: an isolated repulsive system's energies grow as exp(2 Omega t)",
                    0) == 0);
  CHECK(error.find("must be <= 343.7") != std::string::npos);
  // The issue's reproduction (Omega * duration = 700, once accepted and ending in NaN).
  CHECK_FALSE(parse_preset(pair_pushing_apart(-1, 700)).preset.has_value());
}

TEST_CASE("the accepted repulsive run stays finite to its end, the analytic map and rk4 alike") {
  for (const char* method : {"analytic", "rk4"}) {
    CAPTURE(method);
    std::string text = pair_pushing_apart(-1, 343);
    text.insert(1, std::string("\"method\": \"") + method + "\", ");
    const PresetParse p = parse_preset(text);
    REQUIRE(p.preset);
    Run run(initial_system(*p.preset), run_plan(*p.preset));
    run.finish();
    CHECK(run.failure() == "");
    // KE = (1/2) sinh^2(Omega t) ~ exp(2 * 343) / 8 ~ 1e297, and PE = -1/2 - KE: E stays -1/2
    // up to the rounding of two numbers of 1e297.
    const Sample& end = run.samples().back();
    CHECK(std::isfinite(end.E));
    CHECK(end.KE > 1e296);
    CHECK(end.PE < -1e296);
  }
}

TEST_CASE("finite inputs whose products leave the range of a double are refused") {
  struct Case {
    std::string json, message;
  };
  const Case cases[] = {
      {with("J", "1e308"), "J: J * M = 1e+308 must stay within +-1e300"},
      {with("particles", R"([{"m": 1e308, "r": [0.1, 0, 0], "v": [0, 0, 0]},
                            {"m": 1e308, "r": [0, 0, 0], "v": [0, 0, 0]}])"),
       "particles: the total mass M = inf must stay <= 1e300"},
      {R"({"J": 1, "particles": [{"m": 1, "r": [1e200, 0, 0], "v": [0, 0, 0]}], "dt": 0.01,
           "duration": 1})",
       "particles: the energies at t = 0 could reach inf"},
      {R"({"J": 0, "particles": [{"m": 1, "r": [0, 0, 0], "v": [1e150, 0, 0]}], "dt": 1,
           "duration": 1e6})",
       "particles: the energies over the run could reach"},
      {R"({"J": 1, "particles": {"count": 10, "position_radius": 1, "velocity": {"speed": 1}},
           "container": {"radius": 1}, "dt": 1e-3,
           "expansion": {"factor": 1e308, "stages": 1000, "tau": 1e-3}})",
       "expansion.factor: the container would grow to R * factor^(stages - 1) = inf, beyond 1e100"},
      {R"({"J": 1, "particles": {"count": 10, "position_radius": 1, "velocity": {"speed": 1}},
           "container": {"radius": 1}, "dt": 1e-3,
           "expansion": {"factor": 10, "stages": 102, "tau": 1e-3}})",
       "expansion.factor: the container would grow to R * factor^(stages - 1) = 1e+101"},
      {with("container", R"({"radius": 1e101})"), "container.radius: must be <= 1e100"},
      {R"({"J": 1, "particles": [{"m": 1, "r": [0, 0, 0], "v": [0, 0, 0]}],
           "container": {"radius": 1e-101}, "dt": 0.01, "duration": 1})",
       "container.radius: must be >= 1e-100"},
      // Euler grows an amplitude by sqrt(1 + (omega dt)^2) a step: here exp(1e6 ln 2) > 1e300.
      {R"({"J": 1, "method": "euler", "particles": [{"m": 1, "r": [0.1, 0, 0], "v": [0, 0, 0]},
           {"m": 1, "r": [-0.1, 0, 0], "v": [0, 0, 0]}], "dt": 0.7071067811865476,
           "duration": 707106.7811865476})",
       "dt: \"euler\" at omega dt = 1 can grow the energies by exp(6.931e+05)"},
      // round(tau / dt) once overflowed into 1 step a stage: 1e6 stages became "valid".
      {R"({"J": 1, "particles": {"count": 10, "position_radius": 1, "velocity": {"speed": 1}},
           "container": {"radius": 1}, "dt": 1e-300,
           "expansion": {"factor": 1.1, "stages": 1000000, "tau": 1e300}})",
       "expansion.tau: tau / dt = inf steps per stage"},
      {R"({"J": 1, "particles": {"count": 10, "position_radius": 1, "velocity": {"speed": 1}},
           "container": {"radius": 1}, "dt": 1e-3,
           "expansion": {"factor": 1.1, "stages": 1000000, "tau": 1.001}})",
       "expansion: must give between 1 and 1e9 steps of dt (got stages * round(tau / dt) = "
       "1.001e+09"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.json);
    const std::string error = error_of(c.json);
    CAPTURE(error);
    CHECK(error.rfind(c.message, 0) == 0);
  }
}

TEST_CASE("euler just inside its growth limit is accepted and ends finite") {
  // omega dt = 1: each step multiplies the energy by 2; 990 steps give 2^990 ~ 1e298 times an
  // energy scale below 1, within 1e300 (997 would not be).
  const char* text = R"({"J": 1, "method": "euler", "particles": [
      {"m": 1, "r": [0.1, 0, 0], "v": [0, 0, 0]}, {"m": 1, "r": [-0.1, 0, 0], "v": [0, 0, 0]}],
      "dt": 0.7071067811865476, "duration": 700.0035713374821})";
  const PresetParse p = parse_preset(text);
  REQUIRE(p.preset);
  CHECK(step_count(*p.preset) == 990);
  Run run(initial_system(*p.preset), run_plan(*p.preset));
  run.finish();
  CHECK(run.failure() == "");
  CHECK(std::isfinite(run.samples().back().E));
}

TEST_CASE("the text must be exactly one JSON object, each key once") {
  CHECK(error_of(with("J", "1").replace(1, 0, "\"J\": 2, ")) ==
        "J: given twice (each key at most once)");
  // Written out whole: a JSON library (with() uses one) keeps only one of two equal keys.
  CHECK(error_of(R"({"J": 1, "particles": [{"m": 1, "m": 2, "r": [0,0,0], "v": [0,0,0]}],
    "container": {"radius": 1}, "dt": 0.01, "duration": 1})") ==
        "particles[0].m: given twice (each key at most once)");
  CHECK(error_of(R"({"J": 1, "particles": [{"m": 1, "r": [0,0,0], "v": [0,0,0]}],
    "container": {"radius": 1, "radius": 1}, "dt": 0.01, "duration": 1})") ==
        "container.radius: given twice (each key at most once)");
  // Text after a NUL byte was never read; anything after the object is refused too.
  CHECK(error_of(std::string(kGood) + std::string("\0{\"J\": 5}", 9)) ==
        "preset: a NUL byte at offset " + std::to_string(std::string(kGood).size()) +
            " (a preset is plain JSON text)");
  CHECK(error_of(std::string(kGood) + " {}").rfind("preset: not valid JSON", 0) == 0);
  CHECK(parse_preset(std::string(kGood) + " \n\t").preset.has_value());
}

TEST_CASE("an echoed value is cut short and its control characters escaped") {
  const std::string long_name(60'000, 'x');
  std::string error = error_of(with("method", "\"" + long_name + "\""));
  CHECK(error.size() < 300);
  CHECK(error.rfind("method: unknown method \"xxxx", 0) == 0);
  CHECK(error.find("...\" (use analytic") != std::string::npos);
  error = error_of(with(long_name, "1"));
  CHECK(error.size() < 400);
  // Longer strings are refused before nlohmann spends seconds reading them.
  const std::string huge(10'000'000, 'x');
  error = error_of(with("method", "\"" + huge + "\""));
  CHECK(error.rfind("preset: the string at offset ", 0) == 0);
  CHECK(error.find("is longer than 65536 bytes") != std::string::npos);
  CHECK(error.size() < 300);
  error = error_of(with("method", R"("\u001b]0;pwned\u0007\u001b[2J")"));
  CHECK(error ==
        "method: unknown method \"\\u001b]0;pwned\\u0007\\u001b[2J\" (use analytic, "
        "euler, euler-cromer, verlet or rk4)");
  // Every byte of a message is printable ASCII or UTF-8, even for a parse error.
  error = error_of(std::string("{\"J\": 1, \"\x1b[2J"));
  for (char c : error) CHECK((unsigned char)c >= 0x20);
}
