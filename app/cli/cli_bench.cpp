// `swarmlab bench headline|fireball|scale`: runs one of the paper's workloads alone and
// prints its wall time and figures (bench/RESULTS.md collects the numbers).

#include "cli/cli_bench.h"

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include "files/preset_file.h"
#include "scenarios/process_memory.h"
#include "scenarios/workloads.h"
#include "swarm/engine/engine.h"
#include "swarm/engine/fast_engine.h"
#include "swarm/physics/diagnostics.h"
#include "swarm/run/run.h"
#include "swarm/run/side_by_side.h"

namespace swarmlab {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// The preset's plan, with --threads if given.
swarm::RunPlan plan_with_threads(const swarm::Preset& preset, const BenchOptions& o) {
  swarm::RunPlan plan = swarm::run_plan(preset);
  if (o.threads > 0) plan.engine.threads = o.threads;
  return plan;
}

std::unique_ptr<swarm::Engine> make(const std::string& engine, swarm::System s,
                                    const swarm::EngineConfig& config) {
  if (engine == "reference") return swarm::make_reference_engine(std::move(s), config);
  return swarm::make_engine(std::move(s), config);
}

void print_memory(long particles) {
  if (const auto peak = swarmlab::scenarios::peak_memory())
    std::printf("%-18s %.1f MiB = %.1f bytes per particle (whole process)\n", "peak memory",
                double(*peak) / (1 << 20), double(*peak) / double(particles));
}

void print_work(const swarm::Engine& engine) {
  if (const auto st = swarm::fast_engine_stats(engine))
    std::printf("%-18s %lld checks, %lld re-bases, %lld rescheduled, %lld two-thread steps\n",
                "fast engine", (long long)st->checks, (long long)st->rebases,
                (long long)(st->expired + st->reschedules), (long long)st->parallel_steps);
}

/// Runs the reference and the chosen engine side by side for `steps` steps and says whether
/// every step had the same hits, and how far the final states are apart.
bool compare_with_reference(const swarm::Preset& preset, const BenchOptions& o) {
  const std::string& engine = o.engine;
  const long steps = o.compare_steps;
  // Both engines run under the same protocol (expansion steps included), sampled every step,
  // so each sample's hits are that step's hits.
  swarm::RunPlan plan = plan_with_threads(preset, o);
  plan.steps = std::min(plan.steps, steps);
  plan.sample_every = 1;
  const swarm::System initial = swarm::initial_system(preset);
  swarm::Run ref(swarm::make_reference_engine(initial, plan.engine), plan);
  swarm::Run run(make(engine, initial, plan.engine), plan);
  long differing = 0;
  while (!ref.finished()) {
    ref.advance(1);
    run.advance(1);
    if (ref.samples().back().hits != run.samples().back().hits) ++differing;
  }
  const double worst = swarm::max_position_difference(ref.engine().system(), run.engine().system());
  std::printf("%-18s first %ld steps, %lld wall hits: %s; final positions differ by %.2e\n",
              "vs reference", plan.steps, (long long)ref.summary().wall_hits,
              differing == 0 ? "the same hits in every step" : "HITS DIFFER", worst);
  return differing == 0;
}

int expansion(const BenchOptions& o) {
  const bool repulsive = o.workload == "fireball";
  const long n = o.particles > 0 ? o.particles : 40000;
  swarm::Preset preset = swarmlab::scenarios::expansion_preset(repulsive, n);
  if (!o.preset_path.empty()) {
    const swarm::PresetParse parsed = read_preset_file(o.preset_path);
    if (!parsed.preset) {
      std::fprintf(stderr, "swarmlab bench: %s\n", parsed.error.c_str());
      return 2;
    }
    preset = swarmlab::scenarios::scaled(*parsed.preset, n);
  }
  const swarm::RunPlan plan = plan_with_threads(preset, o);
  std::printf("%-18s %s\n%-18s %ld particles, %ld steps of dt = %g, %s engine\n", "workload",
              preset.name.c_str(), "", n, plan.steps, plan.dt, o.engine.c_str());
  std::fflush(stdout);

  const Clock::time_point start = Clock::now();
  swarm::Run run(make(o.engine, swarm::initial_system(preset), plan.engine), plan);
  run.finish();
  const double wall = seconds_since(start);
  const swarm::RunSummary s = run.summary();

  std::printf("%-18s %.3f s (set-up, all steps, P and T every step, samples every %ld)\n",
              "wall time", wall, plan.sample_every);
  std::printf("%-18s %.3g particle-steps per second\n", "throughput",
              double(n) * double(plan.steps) / wall);
  std::printf("%-18s %lld\n%-18s %.3e\n", "wall_hits", (long long)s.wall_hits, "energy_drift",
              s.energy_drift);
  print_work(run.engine());
  print_memory(n);
  std::printf("\n%6s %10s %14s %14s %10s\n", "stage", "R", "P", "T", "hits");
  for (std::size_t i = 0; i < run.stages().size(); ++i) {
    const swarm::Stage& st = run.stages()[i];
    std::printf("%6zu %10.5f %14.6g %14.6g %10lld\n", i, st.R, st.P, st.T, (long long)st.hits);
  }
  const swarm::StageFits f = run.fits();
  for (const auto& [name, fit] : {std::pair{"P-V", f.P_V}, {"T-V", f.T_V}, {"P-T", f.P_T}})
    if (fit.valid)
      std::printf("fit %-4s exponent %+.4f  R^2 = %.4f\n", name, fit.slope, fit.r_squared);
  if (o.compare_steps > 0 && !compare_with_reference(preset, o)) return 1;
  return 0;
}

int scale(const BenchOptions& o) {
  const long n = o.particles > 0 ? o.particles : 1000000;
  swarm::Preset preset = swarmlab::scenarios::expansion_preset(o.repulsive, n);
  preset.expansion.reset();  // the first stage's fixed container
  const Clock::time_point start = Clock::now();
  swarm::System initial = swarm::initial_system(preset);
  const double E0 = swarm::total_energy(initial);
  auto engine = make(o.engine, std::move(initial), plan_with_threads(preset, o).engine);
  const double setup = seconds_since(start);
  long hits = 0;
  for (long i = 0; i < o.steps; ++i) hits += engine->step(preset.dt).hits;
  const double E1 = swarm::total_energy(engine->system());
  const double wall = seconds_since(start);
  std::printf(
      "%-18s %s swarm, %ld particles, %ld steps of dt = %g in a fixed container, %s engine\n",
      "workload", o.repulsive ? "repulsive" : "attractive", n, o.steps, preset.dt,
      o.engine.c_str());
  std::printf("%-18s %.3f s (of which %.3f s drawing the swarm and building the engine)\n",
              "wall time", wall, setup);
  std::printf("%-18s %.3g particle-steps per second\n", "throughput",
              double(n) * double(o.steps) / (wall - setup));
  std::printf("%-18s %ld\n%-18s %.3e\n", "wall_hits", hits, "energy_drift",
              swarm::relative_energy_change(E0, E1, 0));
  print_work(*engine);
  print_memory(n);
  return 0;
}

}  // namespace

CLI::App* add_bench_subcommand(CLI::App& app, BenchOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "bench",
      "Time a headline workload: headline (the attractive expansion of Fig. 2, "
      "N = 40,000, 500,000 steps), fireball (the same, repulsive), scale (N = 1,000,000)");
  cmd->add_option("workload", o.workload, "headline, fireball or scale")
      ->check(CLI::IsMember({"headline", "fireball", "scale"}));
  cmd->add_option("--particles,-n", o.particles, "Particles (default 40,000; scale: 1,000,000)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--steps", o.steps, "scale: steps (default 10,000)")->check(CLI::PositiveNumber);
  cmd->add_flag("--repulsive", o.repulsive, "scale: J < 0");
  cmd->add_option("--engine", o.engine,
                  "fast (the default engine) or reference (Appendix A as written)")
      ->check(CLI::IsMember({"fast", "reference"}));
  cmd->add_option("--preset", o.preset_path,
                  "headline, fireball: run this preset, scaled to --particles")
      ->check(CLI::ExistingFile);
  cmd->add_option(
         "--compare", o.compare_steps,
         "Afterwards, check the first STEPS steps against the reference engine, step by step")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--threads", o.threads,
                  "Threads for the engine: any count (default: every hardware thread; the "
                  "results are the same)")
      ->check(CLI::Range(1, swarm::kMaxThreads));
  return cmd;
}

int bench_command(const BenchOptions& o) {
  if (o.workload == "scale") return scale(o);
  return expansion(o);
}

}  // namespace swarmlab
