#pragma once
/// Conserved and monitored quantities of a system.

#include "swarm/physics/system.h"

namespace swarm {

double kinetic_energy(const System& s);
/// U = (J/4) sum_{i,k} m_i m_k |r_i - r_k|^2 (eq. 8), summed over every pair: O(N^2).
double potential_energy_pairwise(const System& s);
/// U = (1/2) J M sum_k m_k |r_k - R_cm|^2 (eq. 13 about the moving CM): O(N).
double potential_energy_cm(const System& s);
/// Kinetic plus potential (CM form) energy in the lab frame.
double total_energy(const System& s);

/// The kinetic and the potential (CM form) energy in two passes over the particles, with the
/// same sums as kinetic_energy and potential_energy_cm: for samples of large systems.
struct EnergyParts {
  double kinetic = 0, potential = 0;
};
EnergyParts energy_parts(const System& s);
Vec3 total_momentum(const System& s);
/// The swarm's size: sqrt(sum m |r - R_cm|^2 / M), the mass-weighted rms distance from the CM.
double rms_distance_from_cm(const System& s);

/// What a run's sample reads off the particles, in the two passes of energy_parts: the
/// energies, the CM and the size, each to the bit what energy_parts, cm_position and
/// rms_distance_from_cm give (the same sums in the same order), where those three take eight.
struct SwarmReading {
  EnergyParts energy;
  Vec3 cm = Vec3::Zero();
  double size = 0;
  double G = 0;  ///< sum m r.v about the origin: the virial's G (swarm/measure/virial_balance.h)
  double kinetic_cm = 0;  ///< sum 1/2 m |v - V_cm|^2, in the same pass as KE - |p|^2 / 2M
};
SwarmReading swarm_reading(const System& s);
/// L = sum m (r - R_cm) x (v - V_cm).
Vec3 angular_momentum_cm(const System& s);

}  // namespace swarm
