#include "report/provenance.h"

#include <ctime>
#include <nlohmann/json.hpp>
#include <variant>

#ifdef __EMSCRIPTEN__
#include <emscripten/emscripten.h>
#include <emscripten/version.h>
#else
#include <sys/utsname.h>
#endif

#include "swarm/preset/printable_text.h"
#include "swarmlab_version.h"

namespace swarmlab::report {
namespace {

using json = nlohmann::json;

constexpr const char* kDirty = "-dirty-";

#define SWARMLAB_STRING_OF(x) #x
#define SWARMLAB_STRING(x) SWARMLAB_STRING_OF(x)

/// The compiler's own name and version, as its predefined macros give them.
constexpr const char* kCompiler =
#if defined(__EMSCRIPTEN__)
    "Emscripten " SWARMLAB_STRING(__EMSCRIPTEN_major__) "." SWARMLAB_STRING(
        __EMSCRIPTEN_minor__) "." SWARMLAB_STRING(__EMSCRIPTEN_tiny__) " (clang " __clang_version__ ")";
#elif defined(__clang__)
    "clang " __clang_version__;
#elif defined(__GNUC__)
    "GCC " __VERSION__;
#else
    "unknown";
#endif

/// Text from the system (uname, the compiler) kept to one printable line: it goes into CSV
/// comments and XML, where a line break or a control character would end or break them.
std::string one_line(const std::string& text) { return swarm::printable(text, 200); }

/// kCompiler without the space clang's __clang_version__ ends with ("clang 14.0.6 )").
std::string compiler_name() {
  std::string name = kCompiler;
  for (std::size_t at; (at = name.find(" )")) != std::string::npos;) name.erase(at, 1);
  while (!name.empty() && name.back() == ' ') name.pop_back();
  return name;
}

struct Host {
  std::string os, machine;
};

Host host() {
#ifdef __EMSCRIPTEN__
  // The same wasm runs in a page and, for the tests, under node.
  const bool page = EM_ASM_INT({ return typeof window !== 'undefined' ? 1 : 0; }) != 0;
  return {page ? "browser" : "node", "wasm32"};
#else
  utsname u{};
  if (uname(&u) != 0) return {"unknown", "unknown"};
  return {one_line(std::string(u.sysname) + " " + u.release), one_line(u.machine)};
#endif
}

std::string utc_now() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

json seeds_json(const Seeds& s) {
  json j = json::object();
  if (s.seed) j["seed"] = *s.seed;
  if (s.base) j["base"] = *s.base, j["runs"] = s.runs;
  return j;
}

std::string seeds_line(const Seeds& s) {
  if (s.base)
    return "seeds: master seed " + std::to_string(*s.base) + " and runs 0 to " +
           std::to_string(s.runs - 1) + " (run k starts from run_seed of the two)";
  if (s.seed) return "seeds: " + std::to_string(*s.seed);
  return "seeds: none (the particles are listed)";
}

bool read_text(const json& j, const char* key, std::string& out, std::string& error,
               const char* where = "provenance.") {
  const auto it = j.find(key);
  if (it == j.end() || !it->is_string()) {
    error = std::string(where) + key + ": missing or not text";
    return false;
  }
  out = it->get<std::string>();
  return true;
}

bool read_seed(const json& j, const char* key, std::optional<std::uint64_t>& out,
               std::string& error) {
  const auto it = j.find(key);
  if (it == j.end()) return true;
  if (!it->is_number_unsigned()) {
    error = std::string("provenance.seeds.") + key + ": not a whole number >= 0";
    return false;
  }
  out = it->get<std::uint64_t>();
  return true;
}

}  // namespace

Seeds seeds_of(const swarm::Preset& preset) {
  Seeds s;
  if (const auto* swarm = std::get_if<swarm::SwarmSpec>(&preset.particles)) s.seed = swarm->seed;
  return s;
}

Provenance provenance_now(const Seeds& seeds) {
  Provenance p;
  p.version = SWARMLAB_VERSION;
  const std::size_t dirty = p.version.find(kDirty);
  p.commit = p.version.substr(0, dirty);
  if (p.commit != "unknown") p.clean = dirty == std::string::npos;
  p.compiler = one_line(compiler_name());
  const Host h = host();
  p.os = h.os;
  p.machine = h.machine;
  p.date = utc_now();
  p.seeds = seeds;
  return p;
}

json provenance_json(const Provenance& p) {
  return {{"program", "swarmlab"},
          {"version", p.version},
          {"commit", p.commit},
          {"clean", p.clean ? json(*p.clean) : json(nullptr)},
          {"compiler", p.compiler},
          {"host", {{"os", p.os}, {"machine", p.machine}}},
          {"date", p.date},
          {"seeds", seeds_json(p.seeds)}};
}

std::optional<Provenance> provenance_from_json(const json& j, std::string& error) {
  if (!j.is_object()) {
    error = "provenance: missing or not an object";
    return std::nullopt;
  }
  Provenance p;
  if (!read_text(j, "version", p.version, error) || !read_text(j, "commit", p.commit, error) ||
      !read_text(j, "compiler", p.compiler, error) || !read_text(j, "date", p.date, error))
    return std::nullopt;
  const auto clean = j.find("clean");
  if (clean == j.end() || !(clean->is_boolean() || clean->is_null())) {
    error = "provenance.clean: missing or not true, false or null";
    return std::nullopt;
  }
  if (clean->is_boolean()) p.clean = clean->get<bool>();
  const auto host = j.find("host");
  if (host == j.end() || !host->is_object()) {
    error = "provenance.host: missing or not an object";
    return std::nullopt;
  }
  if (!read_text(*host, "os", p.os, error, "provenance.host.") ||
      !read_text(*host, "machine", p.machine, error, "provenance.host."))
    return std::nullopt;
  const auto seeds = j.find("seeds");
  if (seeds == j.end() || !seeds->is_object()) {
    error = "provenance.seeds: missing or not an object";
    return std::nullopt;
  }
  if (!read_seed(*seeds, "seed", p.seeds.seed, error) || !read_seed(*seeds, "base", p.seeds.base, error))
    return std::nullopt;
  if (p.seeds.base) {
    const auto runs = seeds->find("runs");
    if (runs == seeds->end() || !runs->is_number_integer() || runs->get<long>() < 1) {
      error = "provenance.seeds.runs: missing or not a whole number >= 1";
      return std::nullopt;
    }
    p.seeds.runs = runs->get<long>();
  }
  return p;
}

std::vector<std::string> provenance_lines(const Provenance& p) {
  // Worded without commas: a CSV comment keeps none (csv_comment_lines).
  const std::string tree = !p.clean   ? "(not built from a git checkout)"
                           : *p.clean ? "from commit " + p.commit + " with a clean tree"
                                      : "from commit " + p.commit + " with uncommitted changes";
  // The text is the file's when read back from a record: kept to one printable line.
  return {one_line("made by swarmlab " + p.version + " " + tree),
          one_line("compiler: " + p.compiler), one_line("host: " + p.os + " " + p.machine),
          one_line("date: " + p.date), seeds_line(p.seeds)};
}

std::string csv_comment_lines(const std::vector<std::string>& lines) {
  std::string out;
  for (const std::string& line : lines) {
    std::string text = line;
    for (char& c : text)
      if (c == ',' || c == ';' || c == '\t' || c == '"') c = ' ';
    out += "# " + text + "\n";
  }
  return out;
}

}  // namespace swarmlab::report
