#include "swarm/preset/ensemble_seed.h"

#include <cmath>

#include "math/splitmix.h"
#include "swarm/physics/diagnostics.h"

namespace swarm {

std::uint64_t run_seed(std::uint64_t master, std::uint64_t index) {
  return splitmix64(splitmix64(master) ^ index) >> 11;  // 53 bits: exact in any JSON reader
}

SeededPreset with_seed(const Preset& p, std::uint64_t seed, double perturbation) {
  SeededPreset out;
  Preset seeded = p;
  if (auto* spec = std::get_if<SwarmSpec>(&seeded.particles)) {
    spec->seed = seed;
  } else {
    if (!(perturbation > 0)) {
      out.error =
          "particles: listed particles start every run the same; an ensemble of them needs "
          "--perturb (a small random change of each start drawn from the run's seed)";
      return out;
    }
    auto& listed = std::get<std::vector<Particle>>(seeded.particles);
    System s;
    s.particles = listed;
    const Vec3 R = cm_position(s), V = cm_velocity(s);
    double size2 = 0, speed2 = 0, M = 0;
    for (const Particle& q : listed) {
      size2 += q.m * (q.r - R).squaredNorm();
      speed2 += q.m * (q.v - V).squaredNorm();
      M += q.m;
    }
    // One particle, or all at one point or one speed: move them on the scale of 1.
    const double size = size2 > 0 ? std::sqrt(size2 / M) : 1.0;
    const double speed = speed2 > 0 ? std::sqrt(speed2 / M) : 1.0;
    // The kicks are a generated swarm of the same count, positions and velocities in the
    // unit ball: the same draws natively and in wasm.
    SwarmSpec kicks;
    kicks.count = long(listed.size());
    kicks.position_radius = 1;
    kicks.speed = 1;
    kicks.seed = seed;
    const System k = generate_swarm(kicks);
    for (std::size_t i = 0; i < listed.size(); ++i) {
      listed[i].r += perturbation * size * k.particles[i].r;
      listed[i].v += perturbation * speed * k.particles[i].v;
    }
  }
  if (std::string err = preset_error(seeded); !err.empty()) {
    out.error = err;
    return out;
  }
  out.preset = std::move(seeded);
  return out;
}

}  // namespace swarm
