#include "swarm/physics/floor.h"

namespace swarm {

void bounce_on_floor(Particle& p, const Floor& floor, WallTally& tally) {
  const double vz = p.v.z();
  const double dvz = -(1 + floor.restitution) * vz;
  p.v.z() += dvz;
  tally.floor_hits += 1;
  tally.wall_momentum.z() -= p.m * dvz;
  tally.books.wall_work -= 0.5 * p.m * (1 - floor.restitution * floor.restitution) * vz * vz;
}

}  // namespace swarm
