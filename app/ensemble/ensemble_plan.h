#pragma once
// An ensemble on disk: DIR/plan.json says what it is (the preset's hash, how many runs, the
// master seed, the perturbation, the swarmlab that runs it), DIR/preset.json is the preset,
// DIR/runs/<k>.json are the runs, and DIR/manifest.txt holds one plain `swarmlab run` command
// per run for any runner (GNU parallel, a Slurm array: DIR/array.sbatch).

#include <cstdint>
#include <optional>
#include <string>

#include "swarm/preset/preset.h"

namespace swarmlab::ensemble {

inline constexpr const char* kPlanFormat = "swarmlab ensemble plan";

struct EnsemblePlan {
  std::string preset_hash;
  long runs = 0;
  std::uint64_t seed = 1;  ///< the master seed: run k starts from swarm::run_seed(seed, k)
  double perturbation = 0;  ///< for listed particles (swarm::with_seed)
  std::string version;      ///< the swarmlab that wrote the plan
};

/// The version runs record: they merge only with runs of the same one, since another build
/// may round differently and chaotic runs then differ.
std::string program_version();

/// FNV-1a (64 bits, 16 hex digits) of the preset as preset_to_json writes it: the same preset
/// gives the same hash however its file was formatted.
std::string preset_hash(const swarm::Preset& p);

std::string plan_json(const EnsemblePlan& plan);
struct PlanRead {
  std::optional<EnsemblePlan> plan;
  std::string error;
};
PlanRead parse_plan(const std::string& text);

std::string plan_path(const std::string& dir);
std::string preset_path(const std::string& dir);
std::string run_path(const std::string& dir, long index);

/// The `swarmlab run` command of run `index`, as one shell line (paths quoted): swarmlab is
/// the program to call, dir the ensemble's folder as the runner will see it.
std::string run_command_line(const EnsemblePlan& plan, long index, const std::string& swarmlab,
                             const std::string& dir);
/// Every run's command, one per line, run k on line k + 1.
std::string manifest(const EnsemblePlan& plan, const std::string& swarmlab, const std::string& dir);
/// A Slurm batch script for a job array over the manifest: task i runs line i + 1, at most
/// `at_once` at a time (0: no limit).
std::string slurm_array_script(const EnsemblePlan& plan, const std::string& dir, long at_once);

}  // namespace swarmlab::ensemble
