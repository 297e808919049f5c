#pragma once
// The headless subcommands of swarmlab. Each returns the process exit code.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace swarmlab {

struct RunOptions {
  std::string preset_path;
  std::string out_path;   // RESULT.json, empty: none
  std::string csv_path;   // SAMPLES.csv, empty: none
  std::string plots_dir;  // figures (SVG + CSV) go here, empty: none
  bool png = false;       // also render each figure as PNG
  bool quiet = false;
  int threads = 0;        // engine threads; 0: the default (swarm::default_threads)
  // One run of an ensemble (a manifest's line): the seed its start is drawn from, the
  // perturbation of listed particles, its index and the plan's preset hash, and the record.
  std::optional<std::uint64_t> seed;
  double perturb = 0;
  long run_index = -1;
  std::string preset_hash;  // "": not checked
  std::string record_path;  // DIR/runs/<k>.json, empty: none
};

/// swarmlab ensemble and swarmlab plan: N seeds of a preset into DIR.
struct EnsembleOptions {
  std::string preset_path;
  long seeds = 0;
  std::string dir;
  std::uint64_t seed = 1;  // the master seed
  double perturb = 0;
  int jobs = 0;  // runs at once; 0: every hardware thread
  int threads = 0;  // engine threads per run; 0: 1 when runs share the cores, else the default
  bool quiet = false;
  bool dt_check = false;  // ensemble only: the same seeds again at dt / 2 (ensemble/dt_check.h)
  // plan only
  bool slurm = false;
  long slurm_at_once = 0;
  std::string swarmlab;  // the program the manifest calls; "": this one
};

struct MergeOptions {
  std::string dir;
  std::string out_path;  // "": DIR/report.json
  std::string csv_path;  // "": DIR/runs.csv
  double half_width = 0.01;
  bool quiet = false;
};

struct ReportOptions {
  std::vector<std::string> result_paths;  // RESULT.json files from `run --out`
  std::string plots_dir;
  bool png = false;
  bool quiet = false;
};

/// swarmlab check-lesson: the claims of each lesson's steps run and judged.
struct CheckLessonOptions {
  std::vector<std::string> lesson_paths;
  int jobs = 0;  // runs at once; 0: every hardware thread
  bool quiet = false;
};

int run_command(const RunOptions& options);
int validate_command(const std::string& preset_path);
int report_command(const ReportOptions& options);
int ensemble_command(const EnsembleOptions& options);
int plan_command(const EnsembleOptions& options);
int merge_command(const MergeOptions& options);
int check_lesson_command(const CheckLessonOptions& options);

}  // namespace swarmlab
