// Appendix B walls and contacts: steps per second of a hard-sphere gas (the goals: 4,000
// spheres at >= 500 steps/s, 40,000 at >= 50), and the cost per step of a thermal wall and a
// moving wall against the same gas with the plain elastic wall (fast engine and reference).
// Run: build-dir/bench/swarm_bench --benchmark_filter=walls (see bench/RESULTS.md).

#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>

#include "swarm/engine/engine.h"
#include "swarm/engine/fast_engine.h"
#include "swarm/preset/initial_conditions.h"

namespace {

using namespace swarm;

/// N unit masses at temperature 1 (J = 0) in a ball of radius 1: the shipped presets' gas.
System gas(long n) {
  SwarmSpec spec;
  spec.count = n;
  spec.position_radius = 0.9;
  spec.velocities = SwarmSpec::Velocities::maxwell;
  spec.temperature = 1;
  spec.cm_at_rest = true;
  spec.seed = 14;
  System s = generate_swarm(spec);
  s.J = 0;
  return s;
}

void run_steps(benchmark::State& state, std::unique_ptr<Engine> engine, double dt) {
  for (int i = 0; i < 200; ++i) engine->step(dt);  // past the start
  long hits = 0;
  for (auto _ : state) hits += engine->step(dt).hits;
  state.SetItemsProcessed(state.iterations() * state.range(0));
  state.counters["steps/s"] =
      benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["hits/step"] = double(hits) / double(state.iterations());
}

/// Hard spheres filling 15 % of the room the centres have (the shipped preset's packing), on
/// state.range(1) threads.
void BM_HardSpheres(benchmark::State& state) {
  const long n = long(state.range(0));
  EngineConfig config;
  config.threads = int(state.range(1));
  config.container_radius = 1.0;
  config.sphere_radius = std::cbrt(0.15 / double(n)) * 0.9;
  run_steps(state, make_engine(gas(n), config), 1e-3);
}

/// 0: plain wall, fast engine; 1: plain wall, reference engine; 2: thermal wall; 3: moving.
template <int Wall>
void BM_Wall(benchmark::State& state) {
  EngineConfig config;
  config.container_radius = 1.0;
  if (Wall == 2) config.wall_temperature = 1.0;
  if (Wall == 3) config.wall_moves = {{0.5, 1e-3}};
  auto engine = Wall == 1 ? make_reference_engine(gas(long(state.range(0))), config)
                          : make_engine(gas(long(state.range(0))), config);
  run_steps(state, std::move(engine), 1e-3);
}

}  // namespace

BENCHMARK(BM_HardSpheres)->Name("walls/hard_spheres")->ArgsProduct({{4000, 40000}, {1, 2, 4}})->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Wall<0>)->Name("walls/plain_fast")->Arg(4000)->Arg(40000)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Wall<1>)->Name("walls/plain_reference")->Arg(4000)->Arg(40000)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Wall<2>)->Name("walls/thermal")->Arg(4000)->Arg(40000)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Wall<3>)->Name("walls/moving")->Arg(4000)->Arg(40000)->UseRealTime()->Unit(benchmark::kMillisecond);
