// Reading a preset: the text checked before it is parsed, then every key from JSON into a
// Preset, each refused with one message naming the field.
//
// Index
// [SECTION] Particles: a list or a generator
// [SECTION] Appendix B: gravity, a floor and drag
// [SECTION] Appendix B: walls and contacts
// [SECTION] The top level: every key of a preset
// [SECTION] The text before it is parsed, and parse_preset

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "preset/preset_fields.h"
#include "preset/preset_numbers.h"
#include "swarm/preset/preset.h"
#include "swarm/preset/printable_text.h"
#include "swarm/preset/resource_budget.h"
#include "swarm/preset/strict_json.h"

namespace swarm {
namespace {

using preset_detail::fail;
using preset_detail::Fields;
using preset_detail::format;
using preset_detail::Invalid;
using preset_detail::json;
using preset_detail::require;

constexpr long kMaxParticles = 10'000'000;
constexpr double kMaxSteps = 1e9;

// [SECTION] Particles: a list or a generator -----------------------------------------------

// `path` only names a refusal; it is asked for then, since a list may hold millions of vectors.
template <class Path>
Vec3 vector3(const json& v, const Path& path) {
  if (!v.is_array() || v.size() != 3) fail(path(), "must be an array of 3 numbers [x, y, z]");
  Vec3 out;
  for (int k = 0; k < 3; ++k) {
    const json& x = v[std::size_t(k)];
    out[k] = x.is_number() ? x.get<double>() : 0.0;
    if (!x.is_number() || !std::isfinite(out[k]))
      Fields::number_value(x, path() + "[" + std::to_string(k) + "]");
  }
  return out;
}


std::vector<Particle> particle_list(const json& list) {
  require(!list.empty(), "particles", "must hold at least one particle");
  require(long(list.size()) <= kMaxParticles, "particles",
          "must hold at most " + std::to_string(kMaxParticles) + " particles");
  std::vector<Particle> out;
  out.reserve(list.size());
  for (std::size_t i = 0; i < list.size(); ++i) {
    const Fields f(list[i], "particles[" + std::to_string(i) + "]", {"m", "r", "v"});
    Particle p;
    p.m = f.number("m");
    if (!(p.m > 0)) fail(f.path("m"), "must be > 0");
    if (!f.has("r")) fail(f.path("r"), "missing (an array of 3 numbers is required)");
    if (!f.has("v")) fail(f.path("v"), "missing (an array of 3 numbers is required)");
    p.r = vector3(f.at("r"), [&] { return f.path("r"); });
    p.v = vector3(f.at("v"), [&] { return f.path("v"); });
    out.push_back(p);
  }
  return out;
}

SwarmSpec swarm_spec(const json& j) {
  const Fields f(j, "particles",
                 {"count", "mass", "position_radius", "velocity", "cm_at_rest", "seed"});
  SwarmSpec s;
  s.count = f.integer("count", 1, kMaxParticles);
  if (f.has("mass") && f.at("mass").is_object()) {
    const Fields m(f.at("mass"), "particles.mass", {"min", "max"});
    s.mass_min = m.number("min");
    s.mass_max = m.number("max");
    require(s.mass_min > 0, m.path("min"), "must be > 0");
    require(s.mass_max >= s.mass_min, m.path("max"), "must be >= particles.mass.min");
  } else if (f.has("mass")) {
    if (!f.at("mass").is_number())
      fail(f.path("mass"), "must be a number (equal masses) or {\"min\": a, \"max\": b}");
    s.mass_min = s.mass_max = f.number("mass");
    require(s.mass_min > 0, f.path("mass"), "must be > 0");
  }
  s.position_radius = f.number("position_radius");
  require(s.position_radius > 0, f.path("position_radius"), "must be > 0");
  if (!f.has("velocity"))
    fail(f.path("velocity"), "missing ({\"speed\": s} or {\"temperature\": T} is required)");
  const Fields v(f.at("velocity"), "particles.velocity", {"speed", "temperature"});
  require(v.has("speed") != v.has("temperature"), "particles.velocity",
          "give exactly one of \"speed\" (uniform in a ball) or \"temperature\" (Maxwellian)");
  if (v.has("speed")) {
    s.velocities = SwarmSpec::Velocities::ball;
    s.speed = v.number("speed");
    require(s.speed >= 0, v.path("speed"), "must be >= 0");
  } else {
    s.velocities = SwarmSpec::Velocities::maxwell;
    s.temperature = v.number("temperature");
    require(s.temperature >= 0, v.path("temperature"), "must be >= 0");
  }
  s.cm_at_rest = f.flag("cm_at_rest", false);
  s.seed = std::uint64_t(f.has("seed") ? f.integer("seed", 0, (std::int64_t(1) << 53)) : 1);
  return s;
}

// [SECTION] Appendix B: gravity, a floor and drag ------------------------------------------

void parse_forces(const Fields& f, Preset& p) {
  if (f.has("gravity")) {
    p.gravity = vector3(f.at("gravity"), [] { return std::string("gravity"); });
    // The CM falls g t^2 / 2: keep that and its energy M |g| z far inside a double.
    const double fall = 0.5 * p.gravity->norm() * p.duration * p.duration;
    require(fall <= 1e100, "gravity",
            "|g| duration^2 / 2 = " + format(fall) + " is the fall over the run: at most 1e100");
  }
  if (f.has("floor")) {
    const Fields fl(f.at("floor"), "floor", {"z", "restitution"});
    Floor floor;
    floor.z = fl.number("z");
    floor.restitution = fl.number("restitution", 1.0);
    require(floor.restitution >= 0 && floor.restitution <= 1, fl.path("restitution"),
            "must be in [0, 1] (1: elastic, 0: the particle stops falling)");
    if (p.container_radius)
      require(std::abs(floor.z) < *p.container_radius, fl.path("z"),
              "must lie inside the container, -radius < z < radius (got z = " + format(floor.z) +
                  ", container.radius = " + format(*p.container_radius) + ")");
    p.floor = floor;
  }
  if (f.has("drag")) {
    const Fields d(f.at("drag"), "drag", {"gamma", "b", "particles"});
    require(d.has("gamma") != d.has("b"), "drag",
            "give exactly one of \"gamma\" (on every particle, proportional to its mass) or "
            "\"b\" with \"particles\" (on the listed particles)");
    Drag drag;
    if (d.has("gamma")) {
      require(!d.has("particles"), d.path("particles"),
              "goes with \"b\" (gamma acts on every particle)");
      drag.gamma = d.number("gamma");
      require(drag.gamma > 0, d.path("gamma"), "must be > 0");
      require(drag.gamma * p.dt <= 100, d.path("gamma"),
              "gamma * dt must be <= 100 (got " + format(drag.gamma * p.dt) +
                  "): the drag would stop everything within a step");
    } else {
      drag.b = d.number("b");
      require(drag.b > 0, d.path("b"), "must be > 0");
      if (!d.has("particles"))
        fail(d.path("particles"), "missing (the indices of the particles b acts on)");
      const json& list = d.at("particles");
      require(list.is_array() && !list.empty(), d.path("particles"),
              "must be a non-empty list of particle indices");
      std::set<std::int64_t> seen;
      for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string path = d.path("particles") + "[" + std::to_string(i) + "]";
        require(list[i].is_number_integer(), path, "must be a particle index (0, 1, ...)");
        const long long index = list[i].is_number_unsigned()
                                    ? (long long)std::min<unsigned long long>(
                                          list[i].get<unsigned long long>(), 1ull << 62)
                                    : list[i].get<long long>();
        require(index >= 0, path, "must be >= 0");
        require(seen.insert(index).second, path,
                "lists particle " + std::to_string(index) + " twice");
        drag.particles.push_back(std::size_t(index));
      }
      const auto analytic_needs = [](Method m) { return m == Method::analytic; };
      require(!analytic_needs(p.method), "drag.b",
              "drag on chosen particles breaks the centre-of-mass picture, so it needs a "
              "numerical method (euler, euler-cromer, verlet or rk4), not \"analytic\"; or use "
              "drag.gamma");
      for (std::size_t i = 0; i < p.compare.size(); ++i)
        require(!analytic_needs(p.compare[i]), "compare[" + std::to_string(i) + "]",
                "\"analytic\" cannot run drag.b (drag on chosen particles needs a numerical "
                "method)");
    }
    p.drag = drag;
  }
}

// [SECTION] Appendix B: walls and contacts -------------------------------------------------

constexpr std::size_t kMaxWallMoves = 1000;
/// Wall radii, speeds and temperatures stay far inside a double's range (the energies a
/// moving or hot wall gives are of order M u^2 and N Tw).
constexpr double kLargestWallNumber = 1e100;

/// container.moves and container.wall_temperature.
void parse_wall_model(const Fields& c, Preset& p) {
  if (c.has("moves")) {
    const json& list = c.at("moves");
    if (!list.is_array() || list.empty())
      fail("container.moves", "must be a list of {\"to\": radius, \"speed\": u}, at least one");
    require(list.size() <= kMaxWallMoves, "container.moves",
            "must hold at most " + std::to_string(kMaxWallMoves) + " moves");
    for (std::size_t i = 0; i < list.size(); ++i) {
      const Fields m(list[i], "container.moves[" + std::to_string(i) + "]", {"to", "speed"});
      WallMove w;
      w.to = m.number("to");
      require(w.to > 0 && w.to <= kLargestWallNumber, m.path("to"), "must be in (0, 1e100]");
      w.speed = m.number("speed");
      require(w.speed > 0 && w.speed <= kLargestWallNumber, m.path("speed"),
              "must be in (0, 1e100] (the wall's radial speed, length per time)");
      p.wall_moves.push_back(w);
    }
  }
  if (c.has("wall_temperature")) {
    require(!c.has("moves"), "container.wall_temperature",
            "a wall either moves (moves) or is held at a temperature (wall_temperature), "
            "not both");
    p.wall_temperature = c.number("wall_temperature");
    require(*p.wall_temperature > 0 && *p.wall_temperature <= kLargestWallNumber,
            "container.wall_temperature", "must be in (0, 1e100] (energy units, k_B = 1)");
  }
}

// [SECTION] The top level: every key of a preset -------------------------------------------

Preset parse(const json& j) {
  const Fields f(j, "",
                 {"version", "name", "description", "J", "particles", "container", "method",
                  "collisions", "dt", "duration", "expansion", "sample_every", "compare", "gravity",
                  "floor", "drag", "hard_spheres"});
  if (f.has("version"))
    require(f.at("version") == kPresetVersion, "version",
            "must be " + std::to_string(kPresetVersion) + " (the only preset version so far)");
  Preset p;
  p.name = f.text("name", "");
  p.description = f.text("description", "");
  p.J = f.number("J");

  if (!f.has("particles"))
    fail("particles", "missing (a list of particles or a generator object is required)");
  if (f.at("particles").is_array())
    p.particles = particle_list(f.at("particles"));
  else if (f.at("particles").is_object())
    p.particles = swarm_spec(f.at("particles"));
  else
    fail("particles", "must be a list of particles or a generator object");

  if (f.has("container")) {
    const Fields c(f.at("container"), "container", {"radius", "moves", "wall_temperature"});
    p.container_radius = c.number("radius");
    require(*p.container_radius > 0, "container.radius", "must be > 0");
    parse_wall_model(c, p);
  }
  if (f.has("hard_spheres")) {
    const Fields h(f.at("hard_spheres"), "hard_spheres", {"radius"});
    p.sphere_radius = h.number("radius");
    require(*p.sphere_radius > 0, h.path("radius"), "must be > 0");
  }

  const std::string method = f.text("method", "analytic");
  const auto m = method_named(method);
  require(m.has_value(), "method",
          "unknown method \"" + printable(method) + "\" (use " + method_names_listed() + ")");
  p.method = *m;
  const std::string collisions = f.text("collisions", "paper");
  const auto c = collision_mode_named(collisions);
  require(c.has_value(), "collisions", "must be \"paper\" or \"exact\"");
  p.collisions = *c;
  require(!(p.collisions == CollisionMode::exact && p.method != Method::analytic), "collisions",
          "\"exact\" needs method \"analytic\" (the wall time is solved from the analytic orbit)");

  p.dt = f.number("dt");
  require(p.dt > 0, "dt", "must be > 0");

  if (f.has("expansion")) {
    require(p.container_radius.has_value(), "expansion", "needs a container");
    require(!f.has("duration"), "duration",
            "leave it out when an expansion is given (the run lasts stages * tau)");
    const Fields e(f.at("expansion"), "expansion", {"factor", "stages", "tau", "thermalize"});
    ExpansionProtocol x;
    x.factor = e.number("factor");
    require(x.factor >= 1, e.path("factor"), "must be >= 1 (the container only grows)");
    x.stages = e.integer("stages", 1, 1'000'000);
    x.tau = e.number("tau");
    require(x.tau >= p.dt, e.path("tau"), "must be >= dt");
    // Checked before anything rounds tau / dt to a whole number of steps (which could overflow).
    require(x.tau / p.dt <= kMaxSteps, e.path("tau"),
            "tau / dt = " + format(x.tau / p.dt) + " steps per stage: at most 1e9 steps in all");
    require(double(x.stages) * std::round(x.tau / p.dt) <= kMaxSteps, "expansion",
            "must give between 1 and 1e9 steps of dt (got stages * round(tau / dt) = " +
                format(double(x.stages) * std::round(x.tau / p.dt)) + ")");
    x.thermalize_fraction = e.number("thermalize", 0.8);
    require(x.thermalize_fraction >= 0 && x.thermalize_fraction < 1, e.path("thermalize"),
            "must be in [0, 1)");
    p.expansion = x;
    p.duration = double(x.stages) * double(steps_per_stage(x, p.dt)) * p.dt;
  } else {
    p.duration = f.number("duration");
    require(p.duration > 0, "duration", "must be > 0");
  }
  const double steps =
      p.expansion ? double(p.expansion->stages) * double(steps_per_stage(*p.expansion, p.dt))
                  : std::round(p.duration / p.dt);
  require(steps >= 1 && steps <= kMaxSteps, p.expansion ? "expansion" : "duration",
          "must give between 1 and 1e9 steps of dt (got " + format(steps) + ")");
  if (f.has("sample_every")) p.sample_every = f.integer("sample_every", 1, kMaxParticles * 100);
  if (f.has("compare")) {
    const json& list = f.at("compare");
    if (!list.is_array()) fail("compare", "must be a list of method names");
    for (std::size_t i = 0; i < list.size(); ++i) {
      const std::string path = "compare[" + std::to_string(i) + "]";
      if (!list[i].is_string()) fail(path, "must be a method name");
      const auto other = method_named(list[i].get<std::string>());
      require(other.has_value(), path,
              "unknown method \"" + printable(list[i].get<std::string>()) + "\" (use " +
                  method_names_listed() + ")");
      require(!(p.collisions == CollisionMode::exact && *other != Method::analytic), path,
              "collisions \"exact\" needs method \"analytic\"");
      p.compare.push_back(*other);
    }
  }
  parse_forces(f, p);
  return p;
}

// [SECTION] The text before it is parsed, and parse_preset ---------------------------------

/// nlohmann's tree of a preset takes up to about this many bytes per byte of its text (a list
/// of particles: 8-byte numbers in 16-byte values, vectors and maps around them).
constexpr double kParseBytesPerTextByte = 10;
/// No preset field needs a longer string; nlohmann reads a 100 MB one in seconds, so such text
/// is refused by a scan before it is parsed.
constexpr std::size_t kMaxStringBytes = 65'536;

/// "" or a message about the first string literal longer than kMaxStringBytes.
std::string overlong_string(std::string_view text) {
  bool in_string = false;
  std::size_t start = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (!in_string) {
      if (c == '"') in_string = true, start = i + 1;
    } else if (c == '\\') {
      ++i;
    } else if (c == '"') {
      in_string = false;
    } else if (i - start >= kMaxStringBytes) {
      return "preset: the string at offset " + std::to_string(start) + " (\"" +
             printable(text.substr(start, 40)) + "...\") is longer than " +
             std::to_string(kMaxStringBytes) + " bytes, more than any field takes";
    }
  }
  return {};
}

}  // namespace

PresetParse parse_preset(std::string_view json_text, const ResourceLimits& limits) {
  PresetParse out;
  const double reading = double(json_text.size()) * kParseBytesPerTextByte;
  if (reading > limits.memory_bytes) {
    out.error = "preset: " + format(double(json_text.size())) + " bytes of text need about " +
                format(reading) + " bytes of memory to read (limit " + format(limits.memory_bytes) +
                ")";
    return out;
  }
  // nlohmann stops at a NUL byte as at the end of input, so whatever follows would go unread.
  if (const std::size_t nul = json_text.find('\0'); nul != std::string_view::npos) {
    out.error =
        "preset: a NUL byte at offset " + std::to_string(nul) + " (a preset is plain JSON text)";
    return out;
  }
  if (std::string e = overlong_string(json_text); !e.empty()) {
    out.error = std::move(e);
    return out;
  }
  json j;
  try {
    j = parse_strict_json(json_text);
  } catch (const DuplicateKey& e) {
    out.error = e.what();
    return out;
  } catch (const json::parse_error& e) {
    out.error = "preset: not valid JSON at " + json_syntax_error(e, json_text);
    return out;
  } catch (const json::exception& e) {  // e.g. a number beyond the range of a double
    out.error = "preset: a number cannot be read (" + json_error_text(e) + ")";
    return out;
  }
  try {
    Preset p = parse(j);
    preset_detail::check_consistency(p);
    if (std::string e = unrepresentable_numbers(p); !e.empty()) throw Invalid{std::move(e)};
    if (std::string e = resource_error(p, limits); !e.empty()) throw Invalid{std::move(e)};
    out.preset = std::move(p);
  } catch (const Invalid& e) {
    out.error = e.message;
  } catch (const json::exception& e) {
    out.error = "preset: " + json_error_text(e);
  }
  return out;
}

}  // namespace swarm
