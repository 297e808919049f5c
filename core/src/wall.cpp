#include "swarm/wall.h"

#include <cmath>

namespace swarm {

void WallTally::add(const WallTally& o) {
  hits += o.hits;
  radial_impulse += o.radial_impulse;
  hit_kinetic_energy += o.hit_kinetic_energy;
  wall_momentum += o.wall_momentum;
}

void reflect_at_wall(Particle& p, WallTally& tally) {
  const Vec3 n = p.r.normalized();
  const double v_r = p.v.dot(n);
  const Vec3 dp = -2 * p.m * v_r * n;  // the particle's change of momentum
  tally.hits += 1;
  tally.radial_impulse += std::abs(2 * p.m * v_r);
  tally.hit_kinetic_energy += 0.5 * p.m * p.v.squaredNorm();
  tally.wall_momentum -= dp;
  p.v -= 2 * v_r * n;
}

double sphere_area(double R) { return 4 * M_PI * R * R; }
double sphere_volume(double R) { return 4.0 / 3.0 * M_PI * R * R * R; }

}  // namespace swarm
