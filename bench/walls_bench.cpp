// Appendix B walls and contacts: steps per second of a hard-sphere gas (the goals: 4,000
// spheres at >= 500 steps/s, 40,000 at >= 50), and the cost per step of a thermal wall and a
// moving wall against the same gas with the plain elastic wall, each on the fast engine and on
// the reference engine (the goal: a thermal or moving wall within 2x the plain wall's cost on
// the fast engine).
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

enum class Wall { plain, thermal, moving };

/// The gas against a wall, on the fast engine (Fast) or the reference engine. The thermal wall
/// is at the gas's temperature; the moving wall closes in at 1e-3, a thousandth of the thermal
/// speed.
template <Wall Kind, bool Fast>
void BM_Wall(benchmark::State& state) {
  EngineConfig config;
  config.container_radius = 1.0;
  if (Kind == Wall::thermal) config.wall_temperature = 1.0;
  if (Kind == Wall::moving) config.wall_moves = {{0.5, 1e-3}};
  const System s = gas(long(state.range(0)));
  run_steps(state, Fast ? make_fast_engine(s, config) : make_reference_engine(s, config), 1e-3);
}

}  // namespace

BENCHMARK(BM_HardSpheres)->Name("walls/hard_spheres")->ArgsProduct({{4000, 40000}, {1, 2, 4}})->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Wall<Wall::plain, true>)->Name("walls/plain_fast")->Arg(4000)->Arg(40000)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Wall<Wall::thermal, true>)->Name("walls/thermal_fast")->Arg(4000)->Arg(40000)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Wall<Wall::moving, true>)->Name("walls/moving_fast")->Arg(4000)->Arg(40000)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Wall<Wall::plain, false>)->Name("walls/plain_reference")->Arg(4000)->Arg(40000)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Wall<Wall::thermal, false>)->Name("walls/thermal_reference")->Arg(4000)->Arg(40000)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Wall<Wall::moving, false>)->Name("walls/moving_reference")->Arg(4000)->Arg(40000)->UseRealTime()->Unit(benchmark::kMillisecond);
