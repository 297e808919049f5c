// swarm_bench rows for Appendix B's gravity, floor and mass-proportional drag: the cost of one
// step of the expansion preset's first stage (container R = 1, dt = 0.01) with each feature on,
// beside the plain fast engine and the plain reference engine in the same run, so that the
// ratios in bench/RESULTS.md come from one session. With any of them the analytic method runs
// on the reference engine (fast_engine_applies is false): O(N) a step, not O(hits).

#include <benchmark/benchmark.h>

#include "scenarios/workloads.h"
#include "swarm/engine/engine.h"
#include "swarm/preset/preset.h"

namespace {

using namespace swarm;

enum class Feature { none_fast, none_reference, gravity, gravity_and_floor, gamma_drag };

template <Feature F>
void BM_Forces(benchmark::State& state) {
  const long n = long(state.range(0));
  const Preset preset = swarmlab::scenarios::expansion_preset(false, n);
  EngineConfig config = run_plan(preset).engine;
  if (F == Feature::gravity || F == Feature::gravity_and_floor)
    config.forces.gravity = Vec3(0, 0, -0.5);
  if (F == Feature::gravity_and_floor) config.floor = Floor{-0.5, 1};
  if (F == Feature::gamma_drag) config.forces.drag = Drag{0.1, 0, {}};
  std::unique_ptr<Engine> engine = F == Feature::none_reference
                                       ? make_reference_engine(initial_system(preset), config)
                                       : make_engine(initial_system(preset), config);
  const double dt = preset.dt;
  engine->step(dt);
  for (auto _ : state) benchmark::DoNotOptimize(engine->step(dt));
  state.SetItemsProcessed(state.iterations() * n);
  state.SetLabel("particle-steps/s = items/s");
}

#define SWARM_FORCES_BENCH(feature, name)                                                \
  BENCHMARK(BM_Forces<Feature::feature>)->Name(name)->Arg(4000)->Arg(40000)->Unit(        \
      benchmark::kMillisecond)->UseRealTime()

SWARM_FORCES_BENCH(none_fast, "forces/none-fast-engine");
SWARM_FORCES_BENCH(none_reference, "forces/none-reference-engine");
SWARM_FORCES_BENCH(gravity, "forces/gravity");
SWARM_FORCES_BENCH(gravity_and_floor, "forces/gravity-floor");
SWARM_FORCES_BENCH(gamma_drag, "forces/gamma-drag");

}  // namespace
