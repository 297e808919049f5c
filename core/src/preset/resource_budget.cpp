#include "swarm/preset/resource_budget.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "swarm/preset/preset.h"

namespace swarm {
namespace {

// Bytes per item, measured with /usr/bin/time -v on the CLI (see the report of the
// hostile-input change): the fast engine's whole process peaks at 155-168 bytes per particle
// at N = 1e6; a RESULT.json of N = 1e7 peaked at 16 GB, ~1,400 bytes per final particle on top
// of the engine (nlohmann's tree of {m, r, v} plus its text).
constexpr double kEngineBytesPerParticle = 200;
constexpr double kInitialBytesPerParticle = 56;  // one Particle, the initial copy
constexpr double kOutputBytesPerParticle = 1400;
constexpr double kSampleBytes = 2 * double(sizeof(Sample));  // with a vector's spare capacity
constexpr double kComparisonSampleBytes = 2 * 24;  // a ComparisonSample, likewise
constexpr double kOutputBytesPerSample = 2000;     // JSON tree and text, CSV, figures
/// An inelastic floor takes the analytic method off the fast engine (fast_engine_applies; drag
/// b on chosen particles would too, but presets give it a numerical method only): the reference
/// engine's particle-step costs about as much as 50 of the fast engine's (6e7 against 3e9 a
/// second, bench/RESULTS.md's Throughput table). Gravity, mass-proportional drag and an elastic floor
/// stay on it, at about 1x (drag), 6-13x (gravity) and 12-24x (gravity and a floor) its plain
/// cost per particle-step (bench/forces_bench.cpp, bench/RESULTS.md); with a moving or hot wall
/// as well they are charged the same (not measured).
constexpr double kReferenceParticleStepCost = 50;
constexpr double kForcedParticleStepCost = 15;

bool off_the_fast_engine(const Preset& p) {
  return p.floor && p.floor->restitution != 1 && p.method == Method::analytic;
}

bool forced_on_the_fast_engine(const Preset& p) {
  const bool forces = (p.gravity && *p.gravity != Vec3::Zero()) || p.drag || p.floor;
  return forces && p.method == Method::analytic && !off_the_fast_engine(p);
}

// [Appendix B walls and contacts] Hard spheres run on the reference engine, which steps (and,
// for the prediction, copies) every particle in every step, sorts them into cells and tests
// their neighbours: ~290 ns per particle-step at N = 40,000 against the fast engine's 1.85 ns
// in a container (bench/walls_bench.cpp). A moving or hot wall runs on the fast engine at
// about its plain wall's cost (0.8-1.6x, bench/RESULTS.md), so it costs no more here.
constexpr double kHardSphereCost = 150;
constexpr double kCellGridBytesPerParticle = 32;  // cell, slot and two cell starts

double particle_step_weight(const Preset& p) {
  if (p.sphere_radius) return kHardSphereCost;
  if (off_the_fast_engine(p)) return kReferenceParticleStepCost;
  if (forced_on_the_fast_engine(p)) return kForcedParticleStepCost;
  return 1;
}

/// Why a particle-step of p costs particle_step_weight(p) times the fast engine's.
const char* particle_step_weight_reason(const Preset& p) {
  if (p.sphere_radius) return "hard-sphere contacts";
  if (off_the_fast_engine(p)) return "an inelastic floor: the reference engine";
  return "gravity, a floor or drag";
}

double force_evaluations_per_step(Method m) {
  switch (m) {
    case Method::analytic:
      return 0;
    case Method::euler:
      return 1;
    case Method::euler_cromer:
      return 1;
    case Method::verlet:
      return 2;
    case Method::rk4:
      return 4;
  }
  return 4;
}

std::string amount(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

std::string bytes(double x) {
  const char* unit[] = {"bytes", "kB", "MB", "GB", "TB", "PB"};
  int u = 0;
  while (x >= 1000 && u < 5) x /= 1000, ++u;
  char buf[32];
  std::snprintf(buf, sizeof buf, "~%.3g %s", x, unit[u]);
  return buf;
}

long particle_count(const Preset& p) {
  if (const auto* list = std::get_if<std::vector<Particle>>(&p.particles))
    return long(list->size());
  return std::get<SwarmSpec>(p.particles).count;
}

/// The field that sets the number of particles, as a message names it.
const char* count_field(const Preset& p) {
  return std::holds_alternative<SwarmSpec>(p.particles) ? "particles.count" : "particles";
}

}  // namespace

ResourceLimits browser_limits() {
  ResourceLimits l;
  l.memory_bytes = 1e9;
  l.particle_steps = 1e12;            // minutes at wasm's 1e9-3e9 a second
  l.pair_evaluations = 1e12;          // minutes at ~1e9 a second
  l.pair_evaluations_per_step = 5e7;  // N = 10,000 with euler, 5,000 with rk4: ~0.1 s a step
  return l;
}

ResourceEstimate estimate_resources(const Preset& p, bool with_output_files) {
  ResourceEstimate e;
  e.particles = double(particle_count(p));
  const RunPlan plan = run_plan(p);
  e.steps = double(plan.steps);
  e.runs = 1 + double(p.compare.size());
  // A sample at t = 0, every sample_every steps, and at the end.
  e.samples = std::floor(e.steps / double(plan.sample_every)) + 2;

  e.particle_bytes = e.particles * (kInitialBytesPerParticle + e.runs * kEngineBytesPerParticle);
  if (p.sphere_radius) e.particle_bytes += e.particles * e.runs * kCellGridBytesPerParticle;
  e.sample_bytes =
      e.samples * (e.runs * kSampleBytes + double(p.compare.size()) * kComparisonSampleBytes);
  if (with_output_files)
    e.output_bytes =
        e.particles * kOutputBytesPerParticle + e.samples * e.runs * kOutputBytesPerSample;

  e.particle_steps = e.particles * e.steps * e.runs * particle_step_weight(p);
  const double pairs = e.particles * (e.particles - 1) / 2;
  double evaluations = force_evaluations_per_step(p.method);
  for (Method m : p.compare) evaluations += force_evaluations_per_step(m);
  e.pair_evaluations_per_step = pairs * evaluations;
  e.pair_evaluations = e.pair_evaluations_per_step * e.steps;
  return e;
}

std::string resource_error(const Preset& p, const ResourceLimits& limits, bool with_output_files) {
  const ResourceEstimate e = estimate_resources(p, with_output_files);
  const std::string run_field = p.expansion ? "expansion" : "duration";
  const std::string side_by_side =
      e.runs > 1 ? " (x" + amount(e.runs) + ": the compared methods run beside it)" : "";

  if (e.memory_bytes() > limits.memory_bytes) {
    const std::string need = " need " + bytes(e.memory_bytes()) + " of memory (limit " +
                             bytes(limits.memory_bytes) + ")";
    // Name whichever of the particles or the samples costs more.
    const double per_sample =
        e.runs * kSampleBytes + (with_output_files ? e.runs * kOutputBytesPerSample : 0);
    if (e.samples * per_sample >
        e.particle_bytes + e.particles * (with_output_files ? kOutputBytesPerParticle : 0))
      return std::string(p.sample_every ? "sample_every" : run_field.c_str()) + ": " +
             amount(e.samples) + " samples" + side_by_side + need +
             (p.sample_every ? "; raise sample_every" : "; shorten the run");
    return std::string(count_field(p)) + ": " + amount(e.particles) + " particles" + side_by_side +
           need + (with_output_files ? ", RESULT.json included" : "") + "; use fewer particles";
  }
  if (e.pair_evaluations_per_step > limits.pair_evaluations_per_step)
    return std::string(count_field(p)) + ": " + amount(e.particles) +
           " particles with the pairwise methods need " + amount(e.pair_evaluations_per_step) +
           " pair forces a step (limit " + amount(limits.pair_evaluations_per_step) +
           "); use fewer particles or the analytic method";
  if (e.pair_evaluations > limits.pair_evaluations)
    return run_field + ": " + amount(e.steps) + " steps of " + amount(e.particles) +
           " particles with the pairwise methods need " + amount(e.pair_evaluations) +
           " pair forces (limit " + amount(limits.pair_evaluations) +
           "); shorten the run, raise dt or use fewer particles";
  const double weight = particle_step_weight(p);
  const std::string weighted =
      weight == 1 ? ""
                  : " (x" + amount(weight) +
                        ": " + particle_step_weight_reason(p) +
                        " cost that much more per particle-step)";
  if (e.particle_steps > limits.particle_steps)
    return run_field + ": " + amount(e.particles) + " particles x " + amount(e.steps) + " steps" +
           side_by_side + weighted + " = " + amount(e.particle_steps) + " particle-steps (limit " +
           amount(limits.particle_steps) + "); shorten the run, raise dt or use fewer particles";
  return {};
}

}  // namespace swarm
