#pragma once
/// A container wall that moves (Appendix B): its radius is a function of time, and a particle
/// that hits it leaves with its radial velocity relative to the wall reversed, so compression
/// does work on the gas and expansion takes it back.

#include <cmath>
#include <vector>

#include "swarm/physics/system.h"
#include "swarm/physics/wall.h"

namespace swarm {

/// One leg of the wall's path: move radially at `speed` (> 0, length/time) until the radius
/// is `to`, then take the next leg; after the last the wall stays.
struct WallMove {
  double to = 1.0;
  double speed = 1.0;
};

/// The radius of a wall that starts at R0 at t = 0 and makes the moves in turn.
class WallPath {
 public:
  WallPath(double R0, std::vector<WallMove> moves);
  /// The radius at time t (t <= 0: R0; after the last move: its `to`).
  double radius_at(double t) const;
  /// The time at which the last move ends.
  double end_time() const;
  /// The smallest radius the wall has at any time in [t0, t1] (t0 <= t1).
  double lowest_between(double t0, double t1) const;

 private:
  double R0_;
  std::vector<WallMove> moves_;
  std::vector<double> starts_;  ///< the time each move starts
};

/// Reflects particle p off a wall whose radial velocity is u (> 0 outward), at p's position:
/// v_r - u becomes u - v_r. The particle's kinetic energy changes by the work the wall does,
/// which is added to tally.books.wall_work; the radial impulse 2 m |v_r - u| is recorded as a
/// hit. u = 0 gives the elastic reflection of reflect_at_wall.
void reflect_off_moving_wall(Particle& p, double u, WallTally& tally);

/// The same for a particle of mass m at r with velocity v: records the hit and the work and
/// returns the change of velocity, 2 (u - v_r) r / |r|. Inline: the fast engine calls it at
/// every hit.
inline Vec3 moving_wall_reflection(double m, const Vec3& r, const Vec3& v, double u,
                                   WallTally& tally) {
  const Vec3 n = r.normalized();
  const double v_r = v.dot(n);
  const double kinetic_before = 0.5 * m * v.squaredNorm();
  const Vec3 dv = 2 * (u - v_r) * n;
  tally.hits += 1;
  tally.radial_impulse += std::abs(2 * m * (v_r - u));
  tally.hit_kinetic_energy += kinetic_before;
  tally.wall_momentum -= m * dv;
  tally.books.wall_work += 0.5 * m * (v + dv).squaredNorm() - kinetic_before;
  return dv;
}

}  // namespace swarm
