#pragma once
/// A hard horizontal floor, the plane z = h, that particles bounce on (Appendix B: an attractive
/// swarm released above a floor under gravity). It is a second wall beside the container's
/// sphere, checked the same way (paper mode: reflected at the start of the step in which the
/// particle would pass below it; exact mode: at the contact time).

#include "swarm/physics/system.h"
#include "swarm/physics/wall.h"

namespace swarm {

struct Floor {
  double z = 0;            ///< height h of the plane (length)
  double restitution = 1;  ///< e in [0, 1]: the vertical velocity leaves as -e v_z
};

/// A particle moving down at or below the floor, or predicted below it while moving down.
inline bool falling_through(const Floor& floor, const Vec3& r_now_or_next, const Vec3& v) {
  return r_now_or_next.z() < floor.z && v.z() < 0;
}

/// Bounces p off the floor: v_z -> -e v_z. Records the hit, the momentum the floor takes up,
/// and the kinetic energy an inelastic bounce takes, (1 - e^2) m v_z^2 / 2, as negative
/// work in tally.books.
void bounce_on_floor(Particle& p, const Floor& floor, WallTally& tally);

/// After a step on an inelastic floor (e < 1): every particle that ended below the floor is
/// put on it and loses its downward velocity: it rests there, held up as a table holds a
/// ball. A particle that bounces too slowly to clear the floor within a step would otherwise
/// sink by about g dt (1 - e) / (2 (1 + e)) a step (the bounce at the start of the step gives
/// back less than the fall takes). The energy this changes (the lift against gravity g and the
/// springs, the lost downward motion) is booked as the floor's work in tally.books. An elastic
/// floor gives back every bounce in full, so nothing rests on it and nothing is done.
void rest_on_floor(System& s, const Floor& floor, const Vec3& g, WallTally& tally);

}  // namespace swarm
