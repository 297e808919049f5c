// swarmlab ensemble, plan and merge: independent runs of one preset, run here on every core or
// written as a manifest for any runner, and merged into intervals.

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <optional>
#include <thread>

#include "cli/cli.h"
#include "cli/progress_bar.h"
#include "ensemble/dt_check.h"
#include "ensemble/ensemble_member.h"
#include "ensemble/ensemble_plan.h"
#include "ensemble/merge.h"
#include "ensemble/sweep.h"
#include "files/atomic_file.h"
#include "files/text_file.h"
#include "swarm/preset/ensemble_seed.h"
#include "swarm/preset/printable_text.h"

namespace swarmlab {
namespace {

namespace fs = std::filesystem;
using namespace ensemble;

int fail(const std::string& message) {
  std::fprintf(stderr, "error: %s\n", message.c_str());
  return 1;
}

/// The ensemble's folder made or checked, its plan and presets written: "" or why not.
struct Prepared {
  std::string error;
  std::vector<swarm::Preset> presets;  // one per point
  EnsemblePlan plan;
  std::string dir;  // absolute
};

/// The ensemble's folder as an absolute path without a trailing slash.
std::string absolute_folder(const std::string& dir) {
  std::error_code ec;
  std::string out = fs::absolute(dir, ec).lexically_normal().string();
  if (!out.empty() && out.back() == '/') out.pop_back();
  return out;
}

/// `half_dt`: the ensemble's twin for --dt-check, the preset at dt / 2 (ensemble/dt_check.h).
Prepared prepare(const EnsembleOptions& o, int jobs, bool half_dt = false) {
  Prepared out;
  // Read once: the text is a sweep or a preset.
  const std::string text = read_text_file(o.preset_path, out.error);
  if (!out.error.empty()) return out;
  long seeds = o.seeds;
  std::vector<PlanPoint> points;
  if (is_sweep(text) && o.dt_check) {
    out.error = "--dt-check: checks a plain preset's ensemble, not a sweep's";
    return out;
  }
  if (is_sweep(text)) {
    SweepRead sweep = read_sweep(text, o.preset_path);
    if (!sweep.sweep) {
      out.error = o.preset_path + ": " + sweep.error;
      return out;
    }
    if (seeds == 0) seeds = sweep.sweep->seeds.value_or(0);
    for (SweepPoint& p : sweep.sweep->points) {
      points.push_back({p.values, preset_hash(p.preset)});
      out.presets.push_back(std::move(p.preset));
    }
  } else {
    swarm::PresetParse parsed = swarm::parse_preset(text);
    if (!parsed.preset) {
      out.error = o.preset_path + ": " + parsed.error;
      return out;
    }
    if (half_dt) {
      // Held to the same rules and limits as a preset read from a file.
      parsed = swarm::parse_preset(swarm::preset_to_json(with_half_dt(*parsed.preset)));
      if (!parsed.preset) {
        out.error = "--dt-check: " + o.preset_path + " at dt / 2: " + parsed.error;
        return out;
      }
    }
    points.push_back({"{}", preset_hash(*parsed.preset)});
    out.presets.push_back(*parsed.preset);
  }
  if (seeds < 1) {
    out.error = "--seeds: how many runs (per point) is missing: give --seeds N, or \"seeds\" in the sweep";
    return out;
  }
  if (const std::string e = runs_limit_error(points.size(), seeds); !e.empty()) {
    out.error = "--seeds: " + e;
    return out;
  }
  out.plan = {points, seeds, o.seed, o.perturb, program_version()};
  double particle_steps = 0, memory = 0;
  for (std::size_t p = 0; p < out.presets.size(); ++p) {
    // Run 0's start says whether the preset can be seeded at all (listed particles need
    // --perturb; a perturbed particle may leave the container).
    if (const swarm::SeededPreset first =
            swarm::with_seed(out.presets[p], swarm::run_seed(o.seed, 0), o.perturb);
        !first.preset) {
      out.error = o.preset_path + ": " +
                  (points.size() > 1 ? "point " + points[p].values + ": " : std::string()) +
                  first.error;
      return out;
    }
    const swarm::ResourceEstimate cost = swarm::estimate_resources(out.presets[p]);
    particle_steps += cost.particle_steps * double(seeds);
    memory = std::max(memory, cost.memory_bytes());
  }
  const swarm::ResourceLimits limits;
  // The runs share this machine's budget when it runs them; a plan's runs go elsewhere.
  const double budget = limits.particle_steps * std::max(1, jobs);
  if (jobs > 0 && particle_steps > budget) {
    char buf[240];
    std::snprintf(buf, sizeof buf,
                  "--seeds: %ld runs need %.3g particle-steps (limit %.3g with %d jobs here); "
                  "use swarmlab plan to run them on more machines",
                  out.plan.runs(), particle_steps, budget, jobs);
    out.error = buf;
    return out;
  }
  const double at_once = double(std::min<long>(jobs, out.plan.runs()));
  if (jobs > 0 && memory * at_once > limits.memory_bytes) {
    char buf[200];
    std::snprintf(buf, sizeof buf, "--jobs: %.0f runs at once need ~%.3g GB (limit %.3g GB)",
                  at_once, memory * at_once / 1e9, limits.memory_bytes / 1e9);
    out.error = buf;
    return out;
  }
  std::error_code ec;
  out.dir = absolute_folder(o.dir);
  fs::create_directories(out.dir + "/runs", ec);
  if (!ec && points.size() > 1) fs::create_directories(out.dir + "/points", ec);
  if (ec) {
    out.error = o.dir + ": cannot make the folder: " + ec.message();
    return out;
  }
  if (const TextFile existing = read_regular_file(plan_path(out.dir)); !existing.missing) {
    const PlanRead old = existing.error.empty() ? parse_plan(existing.text) : PlanRead{{}, existing.error};
    const EnsemblePlan& p = out.plan;
    if (!old.plan) {
      out.error = plan_path(out.dir) + ": " + old.error;
      return out;
    }
    bool same_points = old.plan->points.size() == p.points.size();
    for (std::size_t i = 0; same_points && i < p.points.size(); ++i)
      same_points = old.plan->points[i].preset_hash == p.points[i].preset_hash;
    std::string differs;
    if (!same_points) differs = "another preset or sweep";
    else if (old.plan->seeds != p.seeds) differs = std::to_string(old.plan->seeds) + " seeds";
    else if (old.plan->seed != p.seed) differs = "master seed " + std::to_string(old.plan->seed);
    else if (old.plan->perturbation != p.perturbation) differs = "another --perturb";
    else if (old.plan->version != p.version) differs = "runs by swarmlab " + old.plan->version;
    if (!differs.empty()) {
      out.error = o.dir + ": holds another ensemble (" + differs +
                  "); choose another --out, or remove the folder";
      return out;
    }
  }
  std::string err;
  for (std::size_t p = 0; err.empty() && p < out.presets.size(); ++p)
    err = write_file_atomically(preset_path(out.dir, out.plan, long(p)),
                                swarm::preset_to_json(out.presets[p]));
  if (err.empty()) err = write_file_atomically(plan_path(out.dir), plan_json(out.plan));
  out.error = err;
  return out;
}

std::string this_program() {
  std::error_code ec;
  const fs::path self = fs::canonical("/proc/self/exe", ec);
  return ec ? std::string("swarmlab") : self.string();
}

int write_merge(const std::string& dir, const MergeOptions& o) {
  const MergeReport m = merge_ensemble(dir, o.half_width);
  if (!m.error.empty()) return fail(m.error);
  OutputFiles files;
  std::string err = files.stage(o.out_path.empty() ? dir + "/report.json" : o.out_path, m.json);
  if (err.empty()) err = files.stage(o.csv_path.empty() ? dir + "/runs.csv" : o.csv_path, m.csv);
  if (err.empty()) err = files.commit();
  if (!err.empty()) return fail(err);
  if (!o.quiet) std::printf("%s", m.table.c_str());
  return 0;
}

}  // namespace

namespace {

/// Runs what p's folder lacks (a killed ensemble resumes): 0, or 1 with the message written.
int run_missing(const Prepared& p, const EnsembleOptions& o, int jobs) {
  // A killed ensemble resumes: whole runs are kept, a corrupted file is named and run again.
  const RunScan scan = scan_runs(p.dir, p.plan);
  if (!scan.mixed.empty()) return fail("runs of another ensemble in " + o.dir + ": " + scan.mixed);
  std::vector<long> todo = scan.missing;
  for (const auto& [k, why] : scan.corrupted) {
    std::fprintf(stderr, "runs/%ld.json: %s: running it again\n", k, why.c_str());
    todo.push_back(k);
  }
  std::sort(todo.begin(), todo.end());
  if (!o.quiet && !scan.done.empty())
    std::fprintf(stderr, "%zu of %ld runs already done in %s\n", scan.done.size(),
                 p.plan.runs(), o.dir.c_str());

  std::atomic<std::size_t> next{0}, finished{0};
  std::mutex lock;
  std::string first_error;
  ProgressBar bar("runs", !o.quiet);
  // One engine thread per run when runs share the cores: the bits do not depend on it.
  const int threads = o.threads > 0 ? o.threads : jobs > 1 ? 1 : swarm::default_threads();
  auto worker = [&] {
    for (;;) {
      const std::size_t i = next++;
      if (i >= todo.size()) return;
      const long k = todo[i];
      const std::size_t point = std::size_t(p.plan.point_of(k));
      const std::uint64_t seed = swarm::run_seed(p.plan.seed, std::uint64_t(p.plan.seed_index_of(k)));
      const swarm::SeededPreset seeded =
          swarm::with_seed(p.presets[point], seed, p.plan.perturbation);
      std::string err = seeded.error;
      if (err.empty()) {
        try {
          err = run_member(*seeded.preset,
                           {k, seed, p.plan.points[point].preset_hash, p.plan.version,
                            p.plan.perturbation},
                           run_path(p.dir, k), threads);
        } catch (const std::exception& e) {
          err = e.what();
        }
      }
      std::lock_guard<std::mutex> hold(lock);
      if (!err.empty() && first_error.empty()) first_error = "run " + std::to_string(k) + ": " + err;
      bar.update(double(++finished) / double(todo.size()));
    }
  };
  std::vector<std::thread> pool;
  if (jobs == 1) worker();  // no second thread (the browser's and node's wasm have none)
  for (int j = 0; jobs > 1 && j < std::min<long>(jobs, long(todo.size())); ++j)
    pool.emplace_back(worker);
  for (auto& t : pool) t.join();
  bar.finish();
  if (!first_error.empty()) return fail(first_error);
  return 0;
}

}  // namespace

int ensemble_command(const EnsembleOptions& o) {
  const int jobs = o.jobs > 0 ? o.jobs : int(std::max(1u, std::thread::hardware_concurrency()));
  const Prepared p = prepare(o, jobs);
  if (!p.error.empty()) return fail(p.error);
  // The twin at dt / 2 is prepared before anything runs, so that a preset that cannot be
  // halved is refused at once.
  EnsembleOptions twin = o;
  twin.dir = p.dir + "/" + kDtHalfFolder;
  std::optional<Prepared> half;
  if (o.dt_check) {
    half = prepare(twin, jobs, true);
    if (!half->error.empty()) return fail(half->error);
  }
  if (const int failed = run_missing(p, o, jobs)) return failed;
  if (half) {
    if (!o.quiet) std::fprintf(stderr, "the same seeds at dt / 2, into %s\n", half->dir.c_str());
    if (const int failed = run_missing(*half, twin, jobs)) return failed;
  }
  MergeOptions m;
  m.quiet = o.quiet;
  return write_merge(p.dir, m);
}

namespace {

/// "" when every text that plan writes into the manifest or the Slurm script is safe there
/// (control_character_in), else one message naming the flag. Checked before anything is
/// written.
std::string unsafe_plan_text(const EnsembleOptions& o, const std::string& swarmlab) {
  struct Text {
    const char* flag;
    const char* what;
    std::string text;
  };
  const Text texts[] = {
      {"--out", "the folder's path", absolute_folder(o.dir)},
      {"--swarmlab", o.swarmlab.empty() ? "this swarmlab's own path (give --swarmlab CMD)"
                                        : "the program to call",
       swarmlab},
      {"PRESET", "the preset's path", o.preset_path}};
  for (const Text& t : texts)
    if (const std::string bad = control_character_in(t.text); !bad.empty())
      return std::string(t.flag) + ": " + t.what + " \"" + swarm::printable(t.text) + "\" holds " +
             bad + ", which a runner could obey as the end of a line and a new command; only "
             "printable UTF-8 text may reach a manifest";
  if (o.slurm && absolute_folder(o.dir).find('\\') != std::string::npos)
    return "--out: a backslash in the folder's path stops Slurm naming each task's log by its "
           "number (--output=.../%a.out); choose a folder without one";
  return {};
}

}  // namespace

int plan_command(const EnsembleOptions& o) {
  const std::string swarmlab = o.swarmlab.empty() ? this_program() : o.swarmlab;
  if (const std::string unsafe = unsafe_plan_text(o, swarmlab); !unsafe.empty()) return fail(unsafe);
  const Prepared p = prepare(o, 0);
  if (!p.error.empty()) return fail(p.error);
  OutputFiles files;
  std::string err = files.stage(p.dir + "/manifest.txt", manifest(p.plan, swarmlab, p.dir));
  if (err.empty() && o.slurm) {
    std::error_code ec;
    fs::create_directories(p.dir + "/logs", ec);  // Slurm opens each task's log before it runs
    err = files.stage(p.dir + "/array.sbatch", slurm_array_script(p.plan, p.dir, o.slurm_at_once));
  }
  if (err.empty()) err = files.commit();
  if (!err.empty()) return fail(err);
  if (!o.quiet) {
    std::printf("wrote %s/manifest.txt: %ld runs (%zu points x %ld seeds), one swarmlab run "
                "command per line\n",
                p.dir.c_str(), p.plan.runs(), p.plan.points.size(), p.plan.seeds);
    // The commands as they can be pasted: the folder quoted for the shell.
    std::printf("run them, for example:\n  parallel --joblog %s --resume-failed < %s\n",
                shell_quoted(p.dir + "/joblog").c_str(), shell_quoted(p.dir + "/manifest.txt").c_str());
    if (o.slurm) std::printf("  sbatch %s\n", shell_quoted(p.dir + "/array.sbatch").c_str());
    std::printf("then: swarmlab merge %s\n", shell_quoted(p.dir).c_str());
  }
  return 0;
}

int merge_command(const MergeOptions& o) {
  std::string dir = o.dir;
  while (dir.size() > 1 && dir.back() == '/') dir.pop_back();
  return write_merge(dir, o);
}

}  // namespace swarmlab
