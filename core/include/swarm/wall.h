#pragma once
/// What the container wall receives from the particles that hit it.

#include <cstdint>
#include "swarm/system.h"

namespace swarm {

/// Sums over the wall hits of one step or of an interval.
struct WallTally {
  std::int64_t hits = 0;
  double radial_impulse = 0;          ///< sum |dp_r| = sum 2 m |v_r|, momentum units
  double hit_kinetic_energy = 0;      ///< sum of 1/2 m v^2 of the particles as they hit
  Vec3 wall_momentum = Vec3::Zero();  ///< momentum taken up by the wall: minus the system's change

  void add(const WallTally& other);
};

/// Reflects particle p elastically about the radial direction at its current position and
/// records the hit. The radial velocity is assumed outward.
void reflect_at_wall(Particle& p, WallTally& tally);

double sphere_area(double R);
double sphere_volume(double R);

}  // namespace swarm
