#pragma once
// An ensemble on disk: DIR/plan.json says what it is (its points, each a preset with its hash,
// the runs per point, the master seed, the perturbation, the swarmlab that runs it), the
// presets are DIR/preset.json (one point) or DIR/points/<p>.json (a sweep), the runs are
// DIR/runs/<i>.json, and DIR/manifest.txt holds one plain `swarmlab run` command per run for
// any runner (GNU parallel, a Slurm array: DIR/array.sbatch).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "swarm/preset/preset.h"

namespace swarmlab::ensemble {

inline constexpr const char* kPlanFormat = "swarmlab ensemble plan";
/// The most runs one ensemble holds (points x seeds): a manifest line is about 250 bytes, so
/// its manifest stays near 250 MB, and a plan.json edited to claim more is refused.
inline constexpr long kMaxRuns = 1000000;

/// One point of a sweep: the values its preset's keys were given ({} for a plain ensemble),
/// as JSON text ({"J": 0.5, "particles.count": 2000}), and that preset's hash.
struct PlanPoint {
  std::string values = "{}";
  std::string preset_hash;
};

struct EnsemblePlan {
  std::vector<PlanPoint> points;  ///< one for a plain ensemble
  long seeds = 0;                 ///< runs per point
  std::uint64_t seed = 1;   ///< the master seed: run k of every point starts from run_seed(seed, k)
  double perturbation = 0;  ///< for listed particles (swarm::with_seed)
  std::string version;      ///< the swarmlab that wrote the plan

  long runs() const { return long(points.size()) * seeds; }
  /// Run i is run i % seeds of point i / seeds.
  long point_of(long run) const { return run / seeds; }
  long seed_index_of(long run) const { return run % seeds; }
};

/// The version runs record: they merge only with runs of the same one, since another build
/// may round differently and chaotic runs then differ.
std::string program_version();

/// FNV-1a (64 bits, 16 hex digits) of the preset as preset_to_json writes it: the same preset
/// gives the same hash however its file was formatted.
std::string preset_hash(const swarm::Preset& p);

/// "" when points x seeds is at most kMaxRuns, else a message ("2000 points x 1000000 seeds
/// = 2e+09 runs, more than the 1,000,000 one ensemble may hold").
std::string runs_limit_error(std::size_t points, long seeds);

/// "" when the text may stand in a manifest line or a shell script: valid UTF-8 without a
/// control character (C0 such as newline, carriage return and NUL, DEL, or C1 U+0080-U+009F),
/// any of which a runner could take for the end of a line or a terminal for a command. Else
/// what is wrong and where ("a newline (byte 12)").
std::string control_character_in(const std::string& text);

/// A word the shell passes through unchanged: in single quotes, each ' written as '\''.
std::string shell_quoted(const std::string& s);

std::string plan_json(const EnsemblePlan& plan);
struct PlanRead {
  std::optional<EnsemblePlan> plan;
  std::string error;
};
PlanRead parse_plan(const std::string& text);

std::string plan_path(const std::string& dir);
/// The preset point p runs: DIR/preset.json for a plain ensemble, DIR/points/<p>.json in a sweep.
std::string preset_path(const std::string& dir, const EnsemblePlan& plan, long point);
std::string run_path(const std::string& dir, long run);

/// The `swarmlab run` command of run i, as one shell line (paths quoted): swarmlab is the
/// program to call, dir the ensemble's folder as the runner will see it. Both must pass
/// control_character_in: a quoted newline still ends a manifest's line.
std::string run_command_line(const EnsemblePlan& plan, long run, const std::string& swarmlab,
                             const std::string& dir);
/// Every run's command, one per line, run i on line i + 1.
std::string manifest(const EnsemblePlan& plan, const std::string& swarmlab, const std::string& dir);
/// A Slurm batch script for a job array over the manifest: task i runs line i + 1, at most
/// `at_once` at a time (0: no limit). dir appears only quoted: for bash in single quotes,
/// on the #SBATCH line as Slurm reads it (slurm_quoted); it must pass control_character_in
/// and hold no backslash (with one, Slurm would not put each task's number in its log's name).
std::string slurm_array_script(const EnsemblePlan& plan, const std::string& dir, long at_once);

}  // namespace swarmlab::ensemble
