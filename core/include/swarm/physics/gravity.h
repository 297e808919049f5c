#pragma once
/// A uniform gravitational field g (length/time^2) acting on every particle. It pulls every
/// particle alike, so it moves only the centre of mass (R_cm = R0 + V0 t + g t^2 / 2) and
/// leaves the motion about it, and so the analytic solution, unchanged.

#include "swarm/physics/system.h"

namespace swarm {

/// U_g = -sum m_i g . r_i: the potential energy in the field, zero at the origin.
double gravity_potential_energy(const System& s, const Vec3& g);

}  // namespace swarm
