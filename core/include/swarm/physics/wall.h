#pragma once
/// What the container wall receives from the particles that hit it.

#include <cmath>
#include <cstdint>
#include "swarm/physics/energy_books.h"
#include "swarm/physics/system.h"

namespace swarm {

/// Sums over the wall hits of one step or of an interval.
struct WallTally {
  std::int64_t hits = 0;
  double radial_impulse = 0;          ///< sum |dp_r| = sum 2 m |v_r|, momentum units
  double hit_kinetic_energy = 0;      ///< sum of 1/2 m v^2 of the particles as they hit
  Vec3 wall_momentum = Vec3::Zero();  ///< momentum taken up by the wall: minus the system's change
  EnergyBooks books;                  ///< energy from outside in the step (walls, floor, drag)
  std::int64_t floor_hits = 0;        ///< bounces on the floor (swarm/physics/floor.h), not in hits

  /// Inline: the fast engine adds up every hit's tally.
  void add(const WallTally& other) {
    hits += other.hits;
    radial_impulse += other.radial_impulse;
    hit_kinetic_energy += other.hit_kinetic_energy;
    wall_momentum += other.wall_momentum;
    books.add(other.books);
    floor_hits += other.floor_hits;
  }
};

/// Reflects particle p elastically about the radial direction at its current position and
/// records the hit. The radial velocity is assumed outward.
void reflect_at_wall(Particle& p, WallTally& tally);

/// The same for a particle of mass m at r with velocity v: records the hit and returns the
/// change of velocity, -2 v_r r / |r|. Inline: the fast engine calls it at every hit.
inline Vec3 wall_reflection(double m, const Vec3& r, const Vec3& v, WallTally& tally) {
  const Vec3 n = r.normalized();
  const double v_r = v.dot(n);
  const Vec3 dv = -2 * v_r * n;
  tally.hits += 1;
  tally.radial_impulse += std::abs(2 * m * v_r);
  tally.hit_kinetic_energy += 0.5 * m * v.squaredNorm();
  tally.wall_momentum -= m * dv;  // the wall takes up what the particle loses
  return dv;
}

double sphere_area(double R);
/// The wall's area over a step in which its radius goes from R0 to R1: the volume it sweeps
/// over the distance it moves, 4 pi (R0^2 + R0 R1 + R1^2) / 3, so that a pressure measured
/// over this area times the change of volume is the wall's work in the step exactly (the P-V
/// loop's area equals the work booked). sphere_area(R) when R0 = R1 = R.
double swept_area(double R0, double R1);
double sphere_volume(double R);

}  // namespace swarm
