#pragma once
/// One particle seen from the centre of mass: what the selected particle's card shows.
///
/// Each particle moves as if tied to the CM by its own spring k_i = J M m_i (paper eq. 12),
/// and the potential energy splits exactly into one spring energy per particle (eq. 13 about
/// the moving CM): U = sum_i 1/2 J M m_i |r_i - R_cm|^2. With the kinetic energy in the CM
/// frame, e_i = 1/2 m_i |v_i - V_cm|^2 + 1/2 J M m_i |r_i - R_cm|^2 is conserved by each
/// particle between wall hits, and the lab-frame total energy is
///     E = 1/2 M |V_cm|^2 + sum_i e_i.

#include <optional>

#include "swarm/physics/system.h"

namespace swarm {

struct ParticleOrbit {
  double m = 0;            ///< mass
  double distance = 0;     ///< |r - R_cm| (length)
  double speed = 0;        ///< |v| in the lab frame
  double speed_cm = 0;     ///< |v - V_cm|, in the CM frame
  double kinetic_cm = 0;   ///< 1/2 m |v - V_cm|^2
  double spring = 0;       ///< 1/2 J M m |r - R_cm|^2, its share of the potential energy
  double energy = 0;       ///< kinetic_cm + spring
  /// J M > 0 only: the period 2 pi / sqrt(J M) and the semi-axes of the ellipse it is on now
  /// (the free orbit, until a wall hit changes it).
  std::optional<double> period, semi_major, semi_minor;
};

/// k = J M (1/time^2); cm_position and cm_velocity of the whole system at the same time.
ParticleOrbit particle_orbit(const Particle& p, const Vec3& cm_position, const Vec3& cm_velocity,
                             double k);

}  // namespace swarm
