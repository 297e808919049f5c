// fireball_bench: the fast engine on the repulsive fireball against the straightforward
// Appendix A loop (OpenMP over the particles: each step the CM from the particles, every
// particle's predicted position at t + dt on its closed-form orbit, the wall check, and every
// particle's closed-form step), timed alternately in one process, with the ratio and the
// machine's load beside each pair. Both run the same preset under the same protocol
// (swarm::Run: its stages, the wall's expansion, P and T every step).
//
// Run: build-dir/bench/fireball_bench [--steps S] [--threads T] [--pairs K] [--check STEPS]
//      [--only fast|loop]
// (bench/RESULTS.md, "The fireball against the straightforward loop").

#include <omp.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <memory>
#include <string>

#include "scenarios/workloads.h"
#include "swarm/engine/engine.h"
#include "swarm/engine/fast_engine.h"
#include "swarm/measure/state_hash.h"
#include "swarm/physics/flow.h"
#include "swarm/physics/wall.h"
#include "swarm/run/run.h"
#include "swarm/run/side_by_side.h"

namespace {

using namespace swarm;

/// Appendix A as a student with OpenMP would write it, nothing more: no schedule, no
/// lookahead, every particle touched three times a step.
class StraightforwardLoop final : public Engine {
 public:
  StraightforwardLoop(System initial, const EngineConfig& config, int threads)
      : s_(std::move(initial)), config_(config), threads_(threads) {
    M_ = total_mass(s_);
  }

  WallTally step(double dt) override {
    const long n = long(s_.particles.size());
    Particle* p = s_.particles.data();
    // The CM from the particles.
    double rx = 0, ry = 0, rz = 0, vx = 0, vy = 0, vz = 0;
#pragma omp parallel for num_threads(threads_) reduction(+ : rx, ry, rz, vx, vy, vz)
    for (long i = 0; i < n; ++i) {
      rx += p[i].m * p[i].r.x();
      ry += p[i].m * p[i].r.y();
      rz += p[i].m * p[i].r.z();
      vx += p[i].m * p[i].v.x();
      vy += p[i].m * p[i].v.y();
      vz += p[i].m * p[i].v.z();
    }
    const Vec3 R = Vec3(rx, ry, rz) / M_;
    Vec3 V = Vec3(vx, vy, vz) / M_;
    const Flow f = Flow::over(s_.J * M_, dt);

    // The wall check: predicted outside at t + dt and moving outward now: reflected now.
    WallTally tally;
    if (config_.container_radius) {
      const double R2 = *config_.container_radius * *config_.container_radius;
      const Vec3 R_next = R + V * dt;
      double px = 0, py = 0, pz = 0;  // the summed momentum change
#pragma omp parallel num_threads(threads_) reduction(+ : px, py, pz)
      {
        WallTally mine;
#pragma omp for
        for (long i = 0; i < n; ++i) {
          const Vec3 r1 = R_next + f.c * (p[i].r - R) + f.s * (p[i].v - V);
          if (r1.squaredNorm() > R2 && p[i].v.dot(p[i].r) > 0) {
            const Vec3 dv = wall_reflection(p[i].m, p[i].r, p[i].v, mine);
            p[i].v += dv;
            px += p[i].m * dv.x();
            py += p[i].m * dv.y();
            pz += p[i].m * dv.z();
          }
        }
#pragma omp critical
        tally.add(mine);
      }
      V += Vec3(px, py, pz) / M_;
    }

    // Every particle on its closed-form orbit about the (kicked) CM.
    const Vec3 R_next = R + V * dt;
#pragma omp parallel for num_threads(threads_)
    for (long i = 0; i < n; ++i) {
      const Vec3 x = p[i].r - R, u = p[i].v - V;
      p[i].r = R_next + f.c * x + f.s * u;
      p[i].v = V + f.dc() * x + f.c * u;
    }
    s_.t += dt;
    return tally;
  }

  const System& system() override { return s_; }
  double time() const override { return s_.t; }
  void set_container_radius(std::optional<double> R) override { config_.container_radius = R; }
  std::optional<double> container_radius() const override { return config_.container_radius; }
  const EngineConfig& config() const override { return config_; }
  std::unique_ptr<Engine> clone() const override {
    return std::make_unique<StraightforwardLoop>(*this);
  }

 private:
  System s_;
  EngineConfig config_;
  int threads_;
  double M_ = 0;
};

struct Options {
  long particles = 40000;
  long steps = 0;  // 0: the whole protocol (500,000 steps)
  int threads = 2;
  int pairs = 1;
  long check = 0;
  std::string only;  // "fast" or "loop": time one of them (for a profiler)
};

/// The 1-minute load average, as `uptime` shows it.
std::string load_now() {
  std::ifstream f("/proc/loadavg");
  std::string one, five;
  f >> one >> five;
  return one + " " + five;
}

struct Timing {
  double seconds = 0;
  double cpu_seconds = 0;  // of every thread of the process: what a busy host does not inflate
  long long hits = 0;
  double drift = 0;
  std::uint64_t hash = 0;  // of the final state: a change of the engine that should not
                           // change the numbers must leave it as it was
};

Timing time_run(std::unique_ptr<Engine> engine, const RunPlan& plan) {
  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpu_start = std::clock();
  Run run(std::move(engine), plan);
  run.finish();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double cpu_seconds = double(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  const RunSummary s = run.summary();
  return {seconds, cpu_seconds, s.wall_hits, s.energy_drift, state_hash(run.engine().system())};
}

/// The loop at 1 and at `threads` threads and the fast engine against the reference engine,
/// step by step over the first `steps` steps: the same hits in every step?
bool check_hits(const Preset& preset, RunPlan plan, int threads, long steps) {
  plan.steps = std::min(plan.steps, steps);
  plan.sample_every = 1;
  const System initial = initial_system(preset);
  Run ref(make_reference_engine(initial, plan.engine), plan);
  Run one(std::make_unique<StraightforwardLoop>(initial, plan.engine, 1), plan);
  Run many(std::make_unique<StraightforwardLoop>(initial, plan.engine, threads), plan);
  Run fast(make_fast_engine(initial, plan.engine), plan);
  long differ_one = 0, differ_many = 0, differ_fast = 0;
  while (!ref.finished()) {
    for (Run* r : {&ref, &one, &many, &fast}) r->advance(1);
    const long hits = ref.samples().back().hits;
    differ_one += one.samples().back().hits != hits;
    differ_many += many.samples().back().hits != hits;
    differ_fast += fast.samples().back().hits != hits;
  }
  std::printf("first %ld steps, %lld wall hits in the reference engine; steps whose hits differ:\n",
              plan.steps, (long long)ref.summary().wall_hits);
  const System& r = ref.engine().system();
  std::printf("  loop, 1 thread   %ld (final positions %.2e apart)\n", differ_one,
              max_position_difference(r, one.engine().system()));
  std::printf("  loop, %d threads  %ld (%.2e)\n", threads, differ_many,
              max_position_difference(r, many.engine().system()));
  std::printf("  fast engine      %ld (%.2e)\n", differ_fast,
              max_position_difference(r, fast.engine().system()));
  return differ_one == 0 && differ_many == 0 && differ_fast == 0;
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i];
    const long value = std::atol(argv[i + 1]);
    if (key == "--only")
      o.only = argv[i + 1];
    else if (key == "--particles")
      o.particles = value;
    else if (key == "--steps")
      o.steps = value;
    else if (key == "--threads")
      o.threads = int(value);
    else if (key == "--pairs")
      o.pairs = int(value);
    else if (key == "--check")
      o.check = value;
    else {
      std::fprintf(stderr, "fireball_bench: unknown option %s\n", key.c_str());
      std::exit(2);
    }
  }
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  const Preset preset = swarmlab::scenarios::expansion_preset(true, o.particles);
  RunPlan plan = run_plan(preset);
  plan.engine.threads = o.threads;
  if (o.steps > 0) plan.steps = std::min(plan.steps, o.steps);
  std::printf("fireball: %ld particles, the first %ld of %ld steps, %d threads for both\n",
              o.particles, plan.steps, run_plan(preset).steps, o.threads);
  if (o.check > 0 && !check_hits(preset, plan, o.threads, o.check)) return 1;

  std::printf("%5s %10s %10s %8s %12s %12s %10s %12s %12s %11s %18s %12s\n", "pair", "fast s",
              "loop s", "ratio", "fast cpu s", "loop cpu s", "cpu ratio", "fast hits", "loop hits",
              "load", "fast state hash", "fast drift");
  for (int k = 0; k < o.pairs; ++k) {
    const std::string load = load_now();
    Timing fast, loop;
    if (o.only != "loop")
      fast = time_run(make_fast_engine(initial_system(preset), plan.engine), plan);
    if (o.only != "fast")
      loop = time_run(
          std::make_unique<StraightforwardLoop>(initial_system(preset), plan.engine, o.threads),
          plan);
    std::printf(
        "%5d %10.3f %10.3f %8.2f %12.3f %12.3f %10.2f %12lld %12lld %11s 0x%016llx %12.3e\n", k + 1,
        fast.seconds, loop.seconds, loop.seconds / fast.seconds, fast.cpu_seconds, loop.cpu_seconds,
        loop.cpu_seconds / fast.cpu_seconds, fast.hits, loop.hits, load.c_str(),
        (unsigned long long)fast.hash, fast.drift);
    std::fflush(stdout);
  }
  return 0;
}
