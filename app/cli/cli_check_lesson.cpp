// swarmlab check-lesson: runs each lesson step's claims (lessons/lesson_claim.h) and fails when
// the physics contradicts the marked answer, the outcome or the text. Each side of a claim is
// an ensemble of seeds run by the ensemble's own code (swarm::with_seed, run_seed, record_of),
// every distinct run once, on every core.

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <mutex>
#include <thread>
#include <tuple>

#include "cli/cli.h"
#include "ensemble/ensemble_plan.h"
#include "ensemble/run_record.h"
#include "lessons/lesson_file.h"
#include "swarm/measure/speed_distribution.h"
#include "swarm/preset/ensemble_seed.h"
#include "swarm/run/run.h"

namespace swarmlab {
// Named, not anonymous: the unity build compiles this file with the other subcommands.
namespace check_lesson {

/// One run of a claim's side: a preset and the seed index k.
struct RunKey {
  std::string preset_hash;
  std::uint64_t master = 1;
  int k = 0;
  bool operator<(const RunKey& o) const {
    return std::tie(preset_hash, master, k) < std::tie(o.preset_hash, o.master, o.k);
  }
};

struct RunResult {
  std::map<std::string, double> values;
  std::string failure;
};

struct RunJob {
  RunKey key;
  const swarm::Preset* preset = nullptr;
};

bool listed(const swarm::Preset& p) {
  return std::holds_alternative<std::vector<swarm::Particle>>(p.particles);
}

/// Run k of a side, as `swarmlab ensemble` runs it: the record's values, the first and last
/// sample's energies and size, and T_kinetic where the record has none (the end's).
RunResult run_one(const RunJob& job, int threads) {
  RunResult out;
  swarm::Preset preset = *job.preset;
  const std::uint64_t seed = swarm::run_seed(job.key.master, std::uint64_t(job.key.k));
  if (!listed(preset)) {
    swarm::SeededPreset seeded = swarm::with_seed(preset, seed, 0);
    if (!seeded.preset) {
      out.failure = seeded.error;
      return out;
    }
    preset = *seeded.preset;
  }
  swarm::RunPlan plan = swarm::run_plan(preset);
  plan.engine.threads = threads;
  swarm::Run run(swarm::initial_system(preset), plan);
  run.finish();
  out.failure = run.failure();
  const ensemble::RunRecord record =
      ensemble::record_of({job.key.k, seed, job.key.preset_hash, ensemble::program_version(), 0}, run);
  for (const auto& [name, v] : record.values) out.values[name] = v.value;
  const std::vector<swarm::Sample>& s = run.samples();
  if (!s.empty()) {
    out.values["E_start"] = s.front().E, out.values["E_end"] = s.back().E;
    out.values["KE_start"] = s.front().KE, out.values["KE_end"] = s.back().KE;
    out.values["size_start"] = s.front().size, out.values["size_end"] = s.back().size;
  }
  // The record's T_kinetic is over the wall's window, beside its T; without a wall, the end's.
  if (!out.values.count("T_kinetic"))
    out.values["T_kinetic"] = swarm::kinetic_temperature(run.engine().system());
  return out;
}

std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", x);
  return text;
}

std::string interval(double mean, const std::optional<double>& lo, const std::optional<double>& hi) {
  return lo ? number(mean) + " [" + number(*lo) + ", " + number(*hi) + "]" : number(mean);
}

std::string side_name(const std::string& quantity, const ClaimRuns& runs) {
  std::string name = quantity + " of " + (runs.preset_name.empty() ? "the scene" : runs.preset_name);
  if (!runs.settings.empty()) name += " with " + runs.settings;
  return name;
}

std::string verdict_name(ClaimVerdict v) {
  return v == ClaimVerdict::shown ? "shown" : v == ClaimVerdict::refuted ? "refuted" : "undecided";
}

std::string quoted(const std::string& text) {
  std::string plain = without_emphasis(text);
  if (plain.size() > 60) plain = plain.substr(0, 57) + "...";
  return "\"" + plain + "\"";
}

/// A claim of one step, its values gathered, ready to be judged.
struct Judged {
  std::string a_name, b_name;
  std::vector<double> a, b;
  std::string missing;  // why a value is missing, "" when all are there
};

class Checker {
 public:
  explicit Checker(bool quiet) : quiet_(quiet) {}

  /// Every run the claims need, each distinct (preset, master seed, k) once.
  void plan(const LessonClaim& c) {
    for (const ClaimRuns* side : {&c.runs, c.against_runs ? &*c.against_runs : nullptr}) {
      if (!side) continue;
      const std::string hash = ensemble::preset_hash(side->preset);
      for (int k = 0; k < c.seeds; ++k) {
        const RunKey key{hash, c.seed, k};
        if (results_.count(key)) continue;
        results_[key] = {};
        jobs_.push_back({key, &side->preset});
      }
    }
  }

  void run_all(int jobs) {
    std::atomic<std::size_t> next{0};
    const int threads = jobs > 1 ? 1 : swarm::default_threads();
    std::mutex lock;
    auto worker = [&] {
      for (std::size_t i = next++; i < jobs_.size(); i = next++) {
        RunResult r = run_one(jobs_[i], threads);
        std::lock_guard<std::mutex> hold(lock);
        results_[jobs_[i].key] = std::move(r);
      }
    };
    std::vector<std::thread> pool;
    if (jobs <= 1) worker();
    for (int j = 0; jobs > 1 && j < std::min<int>(jobs, int(jobs_.size())); ++j) pool.emplace_back(worker);
    for (auto& t : pool) t.join();
  }

  std::size_t runs() const { return jobs_.size(); }

  Judged gather(const LessonClaim& c) const {
    Judged j;
    j.a_name = side_name(c.quantity, c.runs);
    const ClaimRuns& b_runs = c.against_runs ? *c.against_runs : c.runs;
    j.b_name = c.against_value ? number(*c.against_value) : side_name(c.against_quantity, b_runs);
    auto value = [&](const ClaimRuns& side, const std::string& q, int k, std::vector<double>& into) {
      const RunResult& r = results_.at({ensemble::preset_hash(side.preset), c.seed, k});
      if (!r.failure.empty()) {
        j.missing = "run " + std::to_string(k) + " of " + side_name(q, side) + " failed: " + r.failure;
        return;
      }
      const auto it = r.values.find(q);
      if (it == r.values.end() || !std::isfinite(it->second))
        j.missing = "run " + std::to_string(k) + " gave no " + side_name(q, side);
      else
        into.push_back(it->second);
    };
    for (int k = 0; k < c.seeds; ++k) {
      value(c.runs, c.quantity, k, j.a);
      if (c.against_value)
        j.b.push_back(*c.against_value);
      else
        value(b_runs, c.against_quantity, k, j.b);
    }
    return j;
  }

  /// One line of the table, and the error lines of a step whose claims do not hold: "" when
  /// they hold.
  std::string check_step(const std::string& file, std::size_t index, const LessonStep& step) {
    std::string errors;
    if (step.claims.empty()) return errors;
    const std::string where = file + ": step " + std::to_string(index + 1);
    const bool choice = step.task && step.task->kind == LessonTask::Kind::choice;
    // choice: per option, whether some claim states something about it, and what was seen.
    std::vector<bool> stated(choice ? step.task->options.size() : 0, false);
    for (std::size_t n = 0; n < step.claims.size(); ++n) {
      const LessonClaim& c = step.claims[n];
      const std::string claim = where + ", claims[" + std::to_string(n) + "]";
      const Judged g = gather(c);
      if (!g.missing.empty()) {
        errors += "error: " + claim + ": " + g.missing + "\n";
        continue;
      }
      const std::string conf = number(100 * c.confidence) + " % intervals, " + std::to_string(c.seeds) +
                               (c.seeds == 1 ? " run (the same every time)" : " seeds");
      auto judge_one = [&](const ClaimRelation& rel, ClaimMeasurement& m) {
        return swarmlab::judge(rel, g.a, g.b, c.tolerance, c.confidence, &m);
      };
      auto numbers = [&](const ClaimRelation& rel, const ClaimMeasurement& m) {
        const std::string r = rel.kind == ClaimRelation::Kind::ratio ? number(rel.ratio) + " b" : "b";
        return "a = " + g.a_name + " = " + interval(m.a_mean, m.a_lo, m.a_hi) + "; b = " + g.b_name +
               " = " + interval(m.b_mean, m.b_lo, m.b_hi) + "; a - " + r + " = " + number(m.difference) +
               " [" + number(m.difference_lo) + ", " + number(m.difference_hi) + "], tolerance +-" +
               number(m.margin) + " (" + conf + ")";
      };
      if (!choice) {
        ClaimMeasurement m;
        const ClaimVerdict v = judge_one(*c.expect, m);
        row(file, index, n, g.a_name, name_of(*c.expect) + " " + g.b_name, m, verdict_name(v));
        if (v != ClaimVerdict::shown)
          errors += "error: " + claim + ": the step states a " + name_of(*c.expect) + " b, but the runs " +
                    (v == ClaimVerdict::refuted ? "refute it" : "cannot decide (more seeds or a longer run)") +
                    ": " + numbers(*c.expect, m) + "\n";
        continue;
      }
      for (std::size_t i = 0; i < c.options.size(); ++i) {
        if (!c.options[i]) continue;
        stated[i] = true;
        ClaimMeasurement m;
        const ClaimVerdict v = judge_one(*c.options[i], m);
        const bool marked = step.task->answer && *step.task->answer == i;
        row(file, index, n, g.a_name, "option " + std::to_string(i) + (marked ? " (marked)" : "") + ": " +
                name_of(*c.options[i]) + " " + g.b_name, m, verdict_name(v));
        const std::string option = "option " + std::to_string(i) + " " + quoted(step.task->options[i]);
        if (marked && v != ClaimVerdict::shown)
          errors += "error: " + claim + ": the marked answer, " + option + ", states a " +
                    name_of(*c.options[i]) + " b, but the runs " +
                    (v == ClaimVerdict::refuted ? "refute it" : "cannot decide (more seeds or a longer run)") +
                    ": " + numbers(*c.options[i], m) + "\n";
        if (!marked && v != ClaimVerdict::refuted)
          errors += "error: " + claim + ": " + option + " is not the marked answer, but the runs " +
                    (v == ClaimVerdict::shown ? "show it" : "cannot rule it out (more seeds or a longer run)") +
                    " (a " + name_of(*c.options[i]) + " b): " + numbers(*c.options[i], m) + "\n";
      }
    }
    if (choice && step.task->answer && !stated[*step.task->answer])
      errors += "error: " + where + ": the marked answer, option " + std::to_string(*step.task->answer) + " " +
                quoted(step.task->options[*step.task->answer]) +
                ", has no claim behind it (its relation is null in every claim)\n";
    return errors;
  }

  const std::string& table() const { return table_; }

 private:
  void row(const std::string& file, std::size_t step, std::size_t n, const std::string& a,
           const std::string& relation, const ClaimMeasurement& m, const std::string& verdict) {
    if (quiet_) return;
    char line[1200];
    std::snprintf(line, sizeof line, "%-46s %4zu %2zu  %-9s  a %-24s b %-24s  %s: %s\n",
                  file.substr(file.find_last_of('/') + 1).c_str(), step + 1, n, verdict.c_str(),
                  interval(m.a_mean, m.a_lo, m.a_hi).c_str(), interval(m.b_mean, m.b_lo, m.b_hi).c_str(),
                  a.c_str(), relation.c_str());
    table_ += line;
  }

  bool quiet_;
  std::map<RunKey, RunResult> results_;
  std::vector<RunJob> jobs_;
  std::string table_;
};

}  // namespace check_lesson

int check_lesson_command(const CheckLessonOptions& o) {
  const auto started = std::chrono::steady_clock::now();
  std::vector<std::pair<std::string, Lesson>> lessons;
  bool failed = false;
  for (const std::string& path : o.lesson_paths) {
    LessonParse parsed = read_lesson_file(path, shipped_preset_lookup(SWARMLAB_PRESET_DIR));
    if (!parsed.lesson) {
      std::fprintf(stderr, "error: %s\n", parsed.error.c_str());
      failed = true;
      continue;
    }
    lessons.emplace_back(path, std::move(*parsed.lesson));
  }
  if (failed) return 1;
  check_lesson::Checker checker(o.quiet);
  std::size_t claims = 0;
  for (const auto& [path, lesson] : lessons)
    for (const LessonStep& s : lesson.steps)
      for (const LessonClaim& c : s.claims) checker.plan(c), ++claims;
  const int jobs = o.jobs > 0 ? o.jobs : int(std::max(1u, std::thread::hardware_concurrency()));
  checker.run_all(jobs);
  std::string errors;
  for (const auto& [path, lesson] : lessons)
    for (std::size_t i = 0; i < lesson.steps.size(); ++i)
      errors += checker.check_step(path + " (" + lesson.id + ")", i, lesson.steps[i]);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  if (!o.quiet) {
    std::printf("%-46s %4s %2s  %-9s  %-26s %-26s  %s\n", "lesson", "step", "#", "verdict", "a", "b",
                "claim");
    std::printf("%s", checker.table().c_str());
    std::printf("%zu claims in %zu lessons, %zu runs, %.1f s\n", claims, lessons.size(), checker.runs(),
                seconds);
  }
  std::fprintf(stderr, "%s", errors.c_str());
  return errors.empty() ? 0 : 1;
}

}  // namespace swarmlab
