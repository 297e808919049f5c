#pragma once
/// Reproducible initial conditions from a seed.

#include <cstdint>

#include "swarm/physics/system.h"

namespace swarm {

/// A swarm drawn at random. The random numbers come from a 64-bit Mersenne twister turned
/// into doubles by our own code, so a seed gives the same swarm on every platform.
struct SwarmSpec {
  long count = 100;
  double mass_min = 1.0;  ///< masses uniform in [mass_min, mass_max]; equal when the two agree
  double mass_max = 1.0;
  double position_radius = 1.0;  ///< positions uniform in a ball of this radius about the origin
  enum class Velocities { ball, maxwell } velocities = Velocities::ball;
  double speed = 1.0;        ///< ball: velocities uniform in a ball of this radius
  double temperature = 1.0;  ///< maxwell: each component normal with variance T / m (k_B = 1)
  bool cm_at_rest = false;   ///< subtract the centre-of-mass velocity afterwards
  std::uint64_t seed = 1;
};

/// The particles of spec (J and t are left for the caller).
System generate_swarm(const SwarmSpec& spec);

}  // namespace swarm
