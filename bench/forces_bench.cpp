// swarm_bench rows for Appendix B's gravity, floor and mass-proportional drag: the cost of one
// step of the expansion preset's first stage (container R = 1, dt = 0.01) with each feature on,
// on the fast engine and on the reference engine, beside the plain fast engine in the same run,
// so that the ratios in bench/RESULTS.md come from one session. The fast engine keeps each
// particle's motion between hits in closed form under all three (fast_engine_applies).
// Every row times the run's first kRunSteps steps over and over (from a copy made after its
// first step): under drag the swarm soon stops reaching the wall, so a longer run would time
// a swarm at rest.

#include <benchmark/benchmark.h>

#include "scenarios/workloads.h"
#include "swarm/engine/engine.h"
#include "swarm/engine/fast_engine.h"
#include "swarm/preset/preset.h"

namespace {

using namespace swarm;

enum class Feature { none, gravity, gravity_and_floor, gamma_drag };
enum class Which { fast, reference };

constexpr long kRunSteps = 1000;  // 10 time units: drag gamma = 0.1 slows the swarm by e^-1

template <Feature F, Which W>
void BM_Forces(benchmark::State& state) {
  const long n = long(state.range(0));
  const Preset preset = swarmlab::scenarios::expansion_preset(false, n);
  EngineConfig config = run_plan(preset).engine;
  if (F == Feature::gravity || F == Feature::gravity_and_floor)
    config.forces.gravity = Vec3(0, 0, -0.5);
  if (F == Feature::gravity_and_floor) config.floor = Floor{-0.5, 1};
  if (F == Feature::gamma_drag) config.forces.drag = Drag{0.1, 0, {}};
  const std::unique_ptr<Engine> start = W == Which::reference
                                            ? make_reference_engine(initial_system(preset), config)
                                            : make_fast_engine(initial_system(preset), config);
  const double dt = preset.dt;
  start->step(dt);
  std::unique_ptr<Engine> engine = start->clone();
  long steps = 0;
  for (auto _ : state) {
    if (++steps % kRunSteps == 0) {
      state.PauseTiming();
      engine = start->clone();
      state.ResumeTiming();
    }
    benchmark::DoNotOptimize(engine->step(dt));
  }
  state.SetItemsProcessed(state.iterations() * n);
  state.SetLabel("particle-steps/s = items/s");
  // The fast engine's work a step, over the run's first kRunSteps steps (FastEngineStats):
  // what bench/RESULTS.md compares beside the time.
  if (W == Which::fast) {
    std::unique_ptr<Engine> counted = start->clone();
    const FastEngineStats before = *fast_engine_stats(*counted);
    for (long s = 1; s < kRunSteps; ++s) counted->step(dt);
    const FastEngineStats after = *fast_engine_stats(*counted);
    const double steps = double(kRunSteps - 1);
    state.counters["checks"] = double(after.checks - before.checks) / steps;
    state.counters["hits"] = double(after.hits - before.hits) / steps;
    state.counters["expired"] = double(after.expired - before.expired) / steps;
  }
}

#define SWARM_FORCES_BENCH(feature, which, name)                                            \
  BENCHMARK(BM_Forces<Feature::feature, Which::which>)->Name(name)->Arg(4000)->Arg(40000)->Unit( \
      benchmark::kMillisecond)->UseRealTime()

SWARM_FORCES_BENCH(none, fast, "forces/none-fast-engine");
SWARM_FORCES_BENCH(gravity, fast, "forces/gravity-fast-engine");
SWARM_FORCES_BENCH(gravity_and_floor, fast, "forces/gravity-floor-fast-engine");
SWARM_FORCES_BENCH(gamma_drag, fast, "forces/gamma-drag-fast-engine");
SWARM_FORCES_BENCH(none, reference, "forces/none-reference-engine");
SWARM_FORCES_BENCH(gravity, reference, "forces/gravity-reference-engine");
SWARM_FORCES_BENCH(gravity_and_floor, reference, "forces/gravity-floor-reference-engine");
SWARM_FORCES_BENCH(gamma_drag, reference, "forces/gamma-drag-reference-engine");

}  // namespace
