#include "bench_workloads.h"

#include <fstream>
#include <string>

namespace swarm::bench {

Preset expansion_preset(bool repulsive, long particles) {
  Preset p;
  p.name = repulsive ? "Repulsive fireball expansion (paper Fig. 3)"
                     : "Attractive swarm expansion (paper Fig. 2)";
  p.J = (repulsive ? -1 : 1) * 5.555555555555556e-05;
  SwarmSpec spec;
  spec.count = 4000;
  spec.mass_min = 4.0;
  spec.mass_max = 5.0;
  spec.position_radius = 1.0;
  spec.speed = 1.0;
  spec.seed = 2025;
  p.particles = spec;
  p.container_radius = 1.0;
  p.method = Method::analytic;
  p.collisions = CollisionMode::paper;
  p.dt = 0.01;
  p.expansion = ExpansionProtocol{1.01, 50, 100.0, 0.8};
  p.duration = 50 * 100.0;
  p.sample_every = 500;
  return scaled(p, particles);
}

Preset scaled(Preset p, long particles) {
  if (auto* spec = std::get_if<SwarmSpec>(&p.particles)) {
    p.J *= double(spec->count) / double(particles);
    spec->count = particles;
  }
  return p;
}

namespace {

std::optional<std::size_t> status_field(const char* name) {
#if defined(__linux__) && !defined(__EMSCRIPTEN__)
  std::ifstream in("/proc/self/status");
  std::string key;
  while (in >> key) {
    if (key == name) {
      std::size_t kib = 0;
      in >> kib;
      return kib * 1024;
    }
    std::getline(in, key);
  }
#else
  (void)name;
#endif
  return std::nullopt;
}

}  // namespace

std::optional<std::size_t> peak_memory() { return status_field("VmHWM:"); }
std::optional<std::size_t> current_memory() { return status_field("VmRSS:"); }

void reset_peak_memory() {
#if defined(__linux__) && !defined(__EMSCRIPTEN__)
  std::ofstream("/proc/self/clear_refs") << "5";  // resets VmHWM to the current RSS
#endif
}

}  // namespace swarm::bench
