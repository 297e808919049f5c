// The same workloads timed natively and as WebAssembly under node (bench/wasm_bench.sh builds
// and runs both): plain C++ with a steady clock, since Google Benchmark is not built for wasm.
// Usage: wasm_bench [threads]   (native only: any count; wasm always runs one thread)

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <string>

#include "scenarios/workloads.h"
#include "swarm/engine/engine.h"
#include "swarm/engine/fast_engine.h"
#include "swarm/methods/integrators.h"
#include "swarm/preset/preset.h"
#include "swarm/preset/strict_json.h"
#include "swarm/run/run.h"

namespace {

using namespace swarm;

/// Threads for every engine and pairwise step: the command line's, else the default.
int g_threads = default_threads();

double seconds(const std::function<void()>& work) {
  const auto start = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// The expansion preset with N particles for its first `stages` stages (all 50: the headline).
double expansion(bool repulsive, long n, long stages, long* hits) {
  Preset p = swarmlab::scenarios::expansion_preset(repulsive, n);
  p.expansion->stages = stages;
  RunPlan plan = run_plan(p);
  plan.engine.threads = g_threads;
  return seconds([&] {
    Run run(make_engine(initial_system(p), plan.engine), plan);
    run.finish();
    *hits = run.summary().wall_hits;
  });
}

/// Builds an engine for N particles and takes `steps` steps; *build is the first part's time.
double engine_steps(bool fast, long n, long steps, long* hits, double* build) {
  Preset p = swarmlab::scenarios::expansion_preset(false, n);
  System s = initial_system(p);
  EngineConfig config;
  config.container_radius = 1.0;
  config.threads = g_threads;
  return seconds([&] {
    std::unique_ptr<Engine> e;
    *build = seconds([&] {
      e = fast ? make_fast_engine(std::move(s), config)
               : make_reference_engine(std::move(s), config);
    });
    *hits = 0;
    for (long i = 0; i < steps; ++i) *hits += e->step(p.dt).hits;
  });
}

double pairwise(Method m, long n, long steps) {
  System s = initial_system(swarmlab::scenarios::expansion_preset(false, n));
  return seconds([&] {
    for (long i = 0; i < steps; ++i) step(m, s, 1e-3, g_threads);
  });
}

/// Particle-steps per second of one engine on the expansion preset with N particles in its
/// first stage (container radius 1), as swarm_bench measures them: the engine is built and its
/// first step (which schedules every particle) taken outside the timing; then steps for at
/// least a quarter of a second.
double throughput(bool fast, bool repulsive, long n) {
  const Preset p = swarmlab::scenarios::expansion_preset(repulsive, n);
  RunPlan plan = run_plan(p);
  plan.engine.threads = g_threads;
  auto e = fast ? make_fast_engine(initial_system(p), plan.engine)
                : make_reference_engine(initial_system(p), plan.engine);
  e->step(plan.dt);
  long steps = 0;
  const double t = seconds([&] {
    const auto start = std::chrono::steady_clock::now();
    while (steps < 3 || std::chrono::steady_clock::now() - start < std::chrono::milliseconds(250)) {
      e->step(plan.dt);
      ++steps;
    }
  });
  return double(steps) * double(n) / t;
}

/// The text of a share link's preset that lists 12,000 particles: about 0.9 MB of JSON, 1.2
/// million characters once base64url-encoded into the address (the browser test's long link).
std::string listed_particles_json(long n) {
  std::string text = R"({"name": "long link", "J": 1e-4, "container": {"radius": 1}, )"
                     R"("dt": 0.01, "duration": 10, "particles": [)";
  char particle[160];
  for (long i = 0; i < n; ++i) {
    auto x = [i](int k) { return 0.5 * std::sin(double(i) * 12.9898 + k * 78.233); };
    std::snprintf(particle, sizeof particle,
                  R"(%s{"m": 1, "r": [%.6f, %.6f, %.6f], "v": [%.6f, %.6f, %.6f]})",
                  i ? ", " : "", x(1), x(2), x(3), x(4), x(5), x(6));
    text += particle;
  }
  return text + "]}";
}

/// Best of five: opening the long link's preset as the app does (strict JSON, every rule) and,
/// as the floor, nlohmann's plain parse of the same text.
void share_link(long n) {
  const std::string text = listed_particles_json(n);
  double open = 1e30, plain = 1e30, strict = 1e30;
  for (int k = 0; k < 5; ++k) {
    open = std::min(open, seconds([&] {
      if (!parse_preset(text).preset) std::abort();
    }));
    strict = std::min(strict, seconds([&] {
      if (parse_strict_json(text).is_null()) std::abort();
    }));
    plain = std::min(plain, seconds([&] {
      if (nlohmann::json::parse(text).is_null()) std::abort();
    }));
  }
  std::printf("%-44s %8.3f s  (strict JSON %.3f s, plain JSON %.3f s: %.1fx, %.1fx)\n",
              ("share link: preset of " + std::to_string(n) + " particles").c_str(), open, strict,
              plain, open / plain, strict / plain);
}

}  // namespace

int main(int argc, char** argv) {
#ifndef __EMSCRIPTEN__
  if (argc > 1) g_threads = std::max(1, std::atoi(argv[1]));
#else
  (void)argc;  // the browser build has one thread
  (void)argv;
#endif
  std::printf("threads %d\n", g_threads);
  share_link(12000);
  long hits = 0;
  double t = expansion(false, 40000, 50, &hits);
  std::printf("%-44s %8.3f s  %ld hits\n", "headline: attractive N=40000, 500000 steps", t, hits);
  t = expansion(true, 40000, 5, &hits);
  std::printf("%-44s %8.3f s  %ld hits\n", "fireball: repulsive N=40000, first 50000 steps", t,
              hits);
  double build = 0;
  t = engine_steps(true, 1000000, 1000, &hits, &build);
  std::printf("%-44s %8.3f s  %ld hits (building the engine: %.3f s)\n",
              "fast: N=1000000, 1000 steps", t, hits, build);
  t = engine_steps(false, 40000, 1000, &hits, &build);
  std::printf("%-44s %8.3f s  %ld hits\n", "reference: N=40000, 1000 steps", t, hits);
  for (const bool fast : {true, false})
    for (const bool repulsive : {false, true}) {
      std::printf("%-9s %-10s particle-steps/s:", fast ? "fast" : "reference",
                  repulsive ? "repulsive" : "attractive");
      for (const long n : {1000L, 10000L, 100000L, 1000000L})
        std::printf("  N=%ld %.2g", n, throughput(fast, repulsive, n));
      std::printf("\n");
    }
  for (Method m : {Method::euler, Method::euler_cromer, Method::verlet, Method::rk4}) {
    t = pairwise(m, 2000, 20);
    std::printf("pairwise %-13s N=2000, 20 steps           %8.3f s  %.1f steps/s\n",
                std::string(name_of(m)).c_str(), t, 20 / t);
  }
  return 0;
}
