// swarm_bench: particle-steps per second of the fast and the reference (straightforward
// Appendix A) engines on the paper's expansion presets, and of the O(N^2) pairwise
// integrators, for N from 1,000 to 1,000,000; plus the fast engine's peak memory per particle,
// and the cost of the one computation the fast engine makes at every wall hit (a wall window).
// Run: build-dir/bench/swarm_bench [--benchmark_filter=...] (see bench/RESULTS.md).

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "engine/fast_engine_window.h"
#include "scenarios/process_memory.h"
#include "scenarios/workloads.h"
#include "swarm/engine/engine.h"
#include "swarm/engine/fast_engine.h"
#include "swarm/methods/integrators.h"

namespace {

using namespace swarm;

/// One step per iteration of the given engine on the expansion preset with N = range(0),
/// in its first stage (container radius 1). The engine is built, and its first step (which
/// schedules every particle) taken, outside the timing.
template <bool Fast, bool Repulsive>
void BM_Engine(benchmark::State& state) {
  const long n = long(state.range(0));
  const Preset preset = swarmlab::scenarios::expansion_preset(Repulsive, n);
  const RunPlan plan = run_plan(preset);
  swarmlab::scenarios::reset_peak_memory();
  const auto before = swarmlab::scenarios::current_memory();
  std::unique_ptr<Engine> engine = Fast
                                       ? make_fast_engine(initial_system(preset), plan.engine)
                                       : make_reference_engine(initial_system(preset), plan.engine);
  engine->step(plan.dt);
  long hits = 0;
  for (auto _ : state) hits += engine->step(plan.dt).hits;
  state.SetItemsProcessed(state.iterations() * n);
  state.counters["hits/step"] = double(hits) / double(state.iterations());
  const auto peak = swarmlab::scenarios::peak_memory();
  if (before && peak) state.counters["B/particle"] = double(*peak - *before) / double(n);
  state.SetLabel("particle-steps/s = items/s");
}

/// One step per iteration of a pairwise integrator, isolated system, N = range(0).
template <Method M>
void BM_Pairwise(benchmark::State& state) {
  const long n = long(state.range(0));
  System s = initial_system(swarmlab::scenarios::expansion_preset(false, n));
  const int threads = default_threads();
  for (auto _ : state) step(M, s, 1e-3, threads);
  state.SetItemsProcessed(state.iterations() * n);
  state.counters["steps/s"] =
      benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}

// Wall-clock time throughout: the fast engine and the pairwise forces use a second thread.
// The fast engine's step cost does not grow with N (only the hits do); the reference's does.
BENCHMARK(BM_Engine<true, false>)
    ->Name("fast/attractive")
    ->RangeMultiplier(10)
    ->Range(1000, 1000000)
    ->Unit(benchmark::kMicrosecond)
    ->UseRealTime();
BENCHMARK(BM_Engine<true, true>)
    ->Name("fast/repulsive")
    ->RangeMultiplier(10)
    ->Range(1000, 1000000)
    ->Unit(benchmark::kMicrosecond)
    ->UseRealTime();
BENCHMARK(BM_Engine<false, false>)
    ->Name("reference/attractive")
    ->RangeMultiplier(10)
    ->Range(1000, 1000000)
    ->Unit(benchmark::kMicrosecond)
    ->UseRealTime();
BENCHMARK(BM_Engine<false, true>)
    ->Name("reference/repulsive")
    ->RangeMultiplier(10)
    ->Range(1000, 1000000)
    ->Unit(benchmark::kMicrosecond)
    ->UseRealTime();

BENCHMARK(BM_Pairwise<Method::euler>)
    ->Name("pairwise/euler")
    ->Arg(1000)
    ->Arg(2000)
    ->Arg(4000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_Pairwise<Method::euler_cromer>)
    ->Name("pairwise/euler-cromer")
    ->Arg(1000)
    ->Arg(2000)
    ->Arg(4000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_Pairwise<Method::verlet>)
    ->Name("pairwise/verlet")
    ->Arg(1000)
    ->Arg(2000)
    ->Arg(4000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_Pairwise<Method::rk4>)
    ->Name("pairwise/rk4")
    ->Arg(1000)
    ->Arg(2000)
    ->Arg(4000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

/// One wall window (fast_engine_window.h) per item: the fast engine computes one after every
/// wall hit, so its cost bounds the cost of a hit from below. The particles of the N = 40,000
/// expansion preset about their CM, with the frame threshold of a 0.02 margin.
template <bool Repulsive>
void BM_Window(benchmark::State& state) {
  const System s = initial_system(swarmlab::scenarios::expansion_preset(Repulsive, 40000));
  const Vec3 R = cm_position(s), V = cm_velocity(s);
  const double k = stiffness(s);
  const fast::Spring spring{k, 1 / std::sqrt(std::abs(k))};
  std::size_t i = 0;
  for (auto _ : state) {
    const Particle& p = s.particles[i];
    benchmark::DoNotOptimize(fast::window_of(p.r - R, p.v - V, spring, 0.98 * 0.98, 0.0));
    i = i + 1 == s.particles.size() ? 0 : i + 1;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Window<false>)->Name("window/attractive");
BENCHMARK(BM_Window<true>)->Name("window/repulsive");

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
