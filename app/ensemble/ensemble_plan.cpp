#include "ensemble/ensemble_plan.h"

#include <cstdio>
#include <nlohmann/json.hpp>

#include "swarm/preset/ensemble_seed.h"
#include "swarmlab_version.h"

namespace swarmlab::ensemble {
namespace {

using json = nlohmann::json;

/// An argument of an #SBATCH line as sbatch reads it (its _get_argument): in double quotes,
/// with \ before each \, ", ' and # (an unescaped # ends the line there for older Slurm), and
/// each % doubled, since a % in --output starts a pattern such as %a.
std::string slurm_quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '\\' || c == '"' || c == '\'' || c == '#') out += '\\';
    out += c;
    if (c == '%') out += '%';
  }
  return out + "\"";
}

std::string number(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

}  // namespace

std::string program_version() { return SWARMLAB_VERSION; }

std::string shell_quoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string runs_limit_error(std::size_t points, long seeds) {
  if (double(points) * double(seeds) <= double(kMaxRuns)) return {};
  char buf[160];
  std::snprintf(buf, sizeof buf,
                "%zu points x %ld seeds = %.4g runs, more than the 1,000,000 one ensemble may hold",
                points, seeds, double(points) * double(seeds));
  return buf;
}

std::string control_character_in(const std::string& text) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    const unsigned char c = (unsigned char)text[i];
    const std::string at = " (byte " + std::to_string(i + 1) + ")";
    if (c == '\n') return "a newline" + at;
    if (c == '\r') return "a carriage return" + at;
    if (c == 0) return "a NUL" + at;
    if (c < 0x20 || c == 0x7f) return "a control character" + at;
    if (c < 0x80) continue;
    // UTF-8: a lead byte and its continuation bytes, no overlong form of an ASCII character.
    const std::size_t n = c >= 0xC2 && c <= 0xDF ? 2 : c >= 0xE0 && c <= 0xEF ? 3
                        : c >= 0xF0 && c <= 0xF4 ? 4 : 0;
    bool whole = n > 0 && i + n <= text.size();
    for (std::size_t k = 1; whole && k < n; ++k) whole = ((unsigned char)text[i + k] & 0xC0) == 0x80;
    if (!whole) return "a byte that is not UTF-8" + at;
    if (c == 0xC2 && (unsigned char)text[i + 1] < 0xA0) return "a C1 control character" + at;
    i += n - 1;
  }
  return {};
}

std::string preset_hash(const swarm::Preset& p) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (unsigned char c : swarm::preset_to_json(p)) {
    h ^= c;
    h *= 0x100000001b3ULL;
  }
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

std::string plan_json(const EnsemblePlan& plan) {
  json points = json::array();
  for (const PlanPoint& p : plan.points)
    points.push_back({{"values", json::parse(p.values)}, {"preset_hash", p.preset_hash}});
  const json j = {{"format", kPlanFormat},     {"points", points},
                  {"seeds", plan.seeds},       {"seed", plan.seed},
                  {"perturbation", plan.perturbation}, {"swarmlab", plan.version}};
  return j.dump(1) + "\n";
}

PlanRead parse_plan(const std::string& text) {
  PlanRead out;
  const json j = json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object() || j.value("format", std::string()) != kPlanFormat) {
    out.error = std::string("not a plan (\"format\": \"") + kPlanFormat + "\")";
    return out;
  }
  EnsemblePlan p;
  if (!j.contains("swarmlab") || !j["swarmlab"].is_string()) {
    out.error = "swarmlab: missing or not text";
    return out;
  }
  if (!j.contains("points") || !j["points"].is_array() || j["points"].empty()) {
    out.error = "points: missing or empty";
    return out;
  }
  for (std::size_t i = 0; i < j["points"].size(); ++i) {
    const json& point = j["points"][i];
    if (!point.is_object() || !point.contains("values") || !point["values"].is_object() ||
        !point.contains("preset_hash") || !point["preset_hash"].is_string()) {
      out.error = "points[" + std::to_string(i) + "]: needs values (an object) and preset_hash (text)";
      return out;
    }
    p.points.push_back({point["values"].dump(), point["preset_hash"]});
  }
  if (!j.contains("seeds") || !j["seeds"].is_number_integer() || j["seeds"].get<long>() < 1 ||
      j["seeds"].get<long>() > 1000000) {
    out.error = "seeds: missing or not a whole number from 1 to 1,000,000";
    return out;
  }
  if (!j.contains("seed") || !j["seed"].is_number_unsigned()) {
    out.error = "seed: missing or not a whole number >= 0";
    return out;
  }
  if (!j.contains("perturbation") || !j["perturbation"].is_number()) {
    out.error = "perturbation: missing or not a number";
    return out;
  }
  if (const std::string e = runs_limit_error(p.points.size(), j["seeds"].get<long>()); !e.empty()) {
    out.error = "points, seeds: " + e;
    return out;
  }
  p.version = j["swarmlab"];
  p.seeds = j["seeds"];
  p.seed = j["seed"];
  p.perturbation = j["perturbation"];
  out.plan = p;
  return out;
}

std::string plan_path(const std::string& dir) { return dir + "/plan.json"; }
std::string preset_path(const std::string& dir, const EnsemblePlan& plan, long point) {
  return plan.points.size() == 1 ? dir + "/preset.json"
                                 : dir + "/points/" + std::to_string(point) + ".json";
}
std::string run_path(const std::string& dir, long index) {
  return dir + "/runs/" + std::to_string(index) + ".json";
}

std::string run_command_line(const EnsemblePlan& plan, long run, const std::string& swarmlab,
                             const std::string& dir) {
  const long point = plan.point_of(run);
  std::string line =
      shell_quoted(swarmlab) + " run " + shell_quoted(preset_path(dir, plan, point)) + " --seed " +
      std::to_string(swarm::run_seed(plan.seed, std::uint64_t(plan.seed_index_of(run))));
  if (plan.perturbation > 0) line += " --perturb " + number(plan.perturbation);
  line += " --run-index " + std::to_string(run) + " --preset-hash " +
          plan.points[std::size_t(point)].preset_hash + " --record " +
          shell_quoted(run_path(dir, run)) + " --quiet";
  return line;
}

std::string manifest(const EnsemblePlan& plan, const std::string& swarmlab, const std::string& dir) {
  std::string out;
  for (long i = 0; i < plan.runs(); ++i) out += run_command_line(plan, i, swarmlab, dir) + "\n";
  return out;
}

std::string slurm_array_script(const EnsemblePlan& plan, const std::string& dir, long at_once) {
  std::string array = "0-" + std::to_string(plan.runs() - 1);
  if (at_once > 0) array += "%" + std::to_string(at_once);
  return "#!/bin/bash\n"
         "# One run of the ensemble in " + shell_quoted(dir) + " per array task: task i runs line\n"
         "# i + 1 of manifest.txt. Submit with: sbatch " + shell_quoted(dir + "/array.sbatch") + "\n"
         "#SBATCH --job-name=swarmlab-ensemble\n"
         "#SBATCH --array=" + array + "\n"
         "#SBATCH --ntasks=1\n"
         "#SBATCH --cpus-per-task=1\n"
         "#SBATCH --output=" + slurm_quoted(dir + "/logs/") + "%a.out\n"
         "set -euo pipefail\n"
         "mkdir -p " + shell_quoted(dir + "/logs") + "\n"
         "line=$(sed -n \"$((SLURM_ARRAY_TASK_ID + 1))p\" " + shell_quoted(dir + "/manifest.txt") + ")\n"
         "[ -n \"$line\" ] || { echo \"no line $((SLURM_ARRAY_TASK_ID + 1)) in the manifest\" >&2; exit 1; }\n"
         "eval \"$line\"\n";
}

}  // namespace swarmlab::ensemble
