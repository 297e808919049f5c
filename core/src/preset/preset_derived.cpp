// What a preset derives for a run: the system at t = 0, the number of steps and the engine's
// settings.

#include <algorithm>
#include <cmath>
#include <variant>
#include <vector>

#include "swarm/preset/preset.h"

namespace swarm {

System initial_system(const Preset& p) {
  System s;
  if (const auto* list = std::get_if<std::vector<Particle>>(&p.particles))
    s.particles = *list;
  else
    s = generate_swarm(std::get<SwarmSpec>(p.particles));
  s.J = p.J;
  s.t = 0;
  return s;
}

long step_count(const Preset& p) {
  if (p.expansion) return p.expansion->stages * steps_per_stage(*p.expansion, p.dt);
  return std::max(1L, std::lround(p.duration / p.dt));
}

RunPlan run_plan(const Preset& p) {
  RunPlan plan;
  plan.engine.method = p.method;
  plan.engine.collisions = p.collisions;
  plan.engine.container_radius = p.container_radius;
  if (p.gravity) plan.engine.forces.gravity = *p.gravity;
  plan.engine.forces.drag = p.drag;
  plan.engine.floor = p.floor;
  plan.engine.wall_moves = p.wall_moves;
  plan.engine.wall_temperature = p.wall_temperature;
  // A generated swarm's seed is the run's: an ensemble's runs then draw their own wall noise.
  if (const auto* swarm = std::get_if<SwarmSpec>(&p.particles)) plan.engine.wall_stream = swarm->seed;
  plan.engine.sphere_radius = p.sphere_radius;
  plan.dt = p.dt;
  plan.steps = step_count(p);
  plan.sample_every = p.sample_every.value_or(std::max(1L, plan.steps / 2000));
  plan.expansion = p.expansion;
  return plan;
}

}  // namespace swarm
