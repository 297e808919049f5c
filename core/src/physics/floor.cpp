#include "swarm/physics/floor.h"

#include "swarm/physics/diagnostics.h"
#include "swarm/physics/gravity.h"

namespace swarm {

void bounce_on_floor(Particle& p, const Floor& floor, WallTally& tally) {
  const double vz = p.v.z();
  const double dvz = -(1 + floor.restitution) * vz;
  p.v.z() += dvz;
  tally.floor_hits += 1;
  tally.wall_momentum.z() -= p.m * dvz;
  tally.books.wall_work -= 0.5 * p.m * (1 - floor.restitution * floor.restitution) * vz * vz;
}

void rest_on_floor(System& s, const Floor& floor, const Vec3& g, WallTally& tally) {
  if (floor.restitution >= 1) return;
  bool any_below = false;
  for (const Particle& p : s.particles) any_below = any_below || p.r.z() < floor.z;
  if (!any_below) return;
  const double E_before = total_energy(s) + gravity_potential_energy(s, g);
  for (Particle& p : s.particles) {
    if (!(p.r.z() < floor.z)) continue;
    p.r.z() = floor.z;
    if (p.v.z() < 0) {
      tally.wall_momentum.z() += p.m * p.v.z();  // the floor takes up the downward momentum
      p.v.z() = 0;
    }
  }
  tally.books.wall_work += total_energy(s) + gravity_potential_energy(s, g) - E_before;
}

}  // namespace swarm
