#include "scenarios/workloads.h"

namespace swarmlab::scenarios {

using namespace swarm;

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

}  // namespace swarmlab::scenarios
