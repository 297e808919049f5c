#pragma once
// The container wall as the fast engine's hit sees it in one step: where it is at the step's
// end, how it moves over the step, and what it does to a particle that leaves: an elastic
// reflection, a reflection off a moving wall, or a re-emission at the wall's temperature.
// The rules are the reference engine's (core/src/engine/reference_engine.cpp), to the bit.

#include <cstdint>

#include "swarm/physics/system.h"
#include "swarm/physics/thermal_wall.h"
#include "swarm/physics/wall.h"
#include "swarm/physics/wall_motion.h"

namespace swarm::fast {

/// One step's sphere wall, for reflect_if_leaving (fast_engine_body.h). A particle hits it when
/// its position predicted for the step's end lies outside the radius the wall has then and it
/// leaves the wall now: moves outward (a fixed or a thermal wall), or outward faster than the
/// wall (a moving one).
struct SphereWall {
  double R2 = 0;        ///< the radius at the step's end, squared
  double u = 0;         ///< a moving wall's mean radial velocity over the step (length/time)
  bool moving = false;  ///< the wall follows a path (WallPath), even once it has stopped
  double temperature = 0;  ///< > 0: a thermal wall at this temperature (energy units)
  std::uint64_t step = 0;    ///< the engine's step count, a thermal draw's key
  std::uint64_t stream = 0;  ///< the run's key (EngineConfig::wall_stream)

  bool outside(const Vec3& r1) const { return r1.squaredNorm() > R2; }

  bool leaving(const Vec3& r0, const Vec3& v0) const {
    if (moving && temperature <= 0) return v0.dot(r0.normalized()) > u;
    return v0.dot(r0) > 0;
  }

  /// The hit of particle `id` (mass m, at r0 with velocity v0): recorded in tally, with the
  /// wall's work or heat in its books; returns the velocity change.
  Vec3 hit(double m, const Vec3& r0, const Vec3& v0, std::uint32_t id, WallTally& tally) const {
    if (temperature > 0)
      return thermal_reemission(m, r0, v0, temperature, {step, id, stream}, tally) - v0;
    if (moving) return moving_wall_reflection(m, r0, v0, u, tally);
    return wall_reflection(m, r0, v0, tally);
  }
};

}  // namespace swarm::fast
