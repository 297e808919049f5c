#include "swarm/physics/diagnostics.h"

#include <cmath>

namespace swarm {

double kinetic_energy(const System& s) {
  double ke = 0;
  for (const auto& p : s.particles) ke += 0.5 * p.m * p.v.squaredNorm();
  return ke;
}

double potential_energy_pairwise(const System& s) {
  double sum = 0;  // over i < k, which is half the double sum of eq. 8
  const auto& ps = s.particles;
  for (std::size_t i = 0; i < ps.size(); ++i)
    for (std::size_t k = i + 1; k < ps.size(); ++k)
      sum += ps[i].m * ps[k].m * (ps[i].r - ps[k].r).squaredNorm();
  return 0.5 * s.J * sum;
}

SwarmReading swarm_reading(const System& s) {
  double M = 0, ke = 0, G = 0;
  Vec3 moment = Vec3::Zero(), momentum = Vec3::Zero();
  for (const auto& p : s.particles) {
    M += p.m;  // total_mass
    moment += p.m * p.r;
    momentum += p.m * p.v;
    ke += 0.5 * p.m * p.v.squaredNorm();
    G += p.m * p.r.dot(p.v);
  }
  const Vec3 R = moment / M;  // cm_position
  double sum = 0;
  for (const auto& p : s.particles) sum += p.m * (p.r - R).squaredNorm();
  return {
      {ke, 0.5 * (s.J * M) * sum}, R, std::sqrt(sum / M), G, ke - 0.5 * momentum.squaredNorm() / M};
}

EnergyParts energy_parts(const System& s) { return swarm_reading(s).energy; }

double potential_energy_cm(const System& s) { return energy_parts(s).potential; }

double total_energy(const System& s) {
  const EnergyParts e = energy_parts(s);
  return e.kinetic + e.potential;
}

Vec3 total_momentum(const System& s) {
  Vec3 P = Vec3::Zero();
  for (const auto& p : s.particles) P += p.m * p.v;
  return P;
}

double rms_distance_from_cm(const System& s) { return swarm_reading(s).size; }

Vec3 angular_momentum_cm(const System& s) {
  const Vec3 R = cm_position(s);
  const Vec3 V = cm_velocity(s);
  Vec3 L = Vec3::Zero();
  for (const auto& p : s.particles) L += p.m * (p.r - R).cross(p.v - V);
  return L;
}

}  // namespace swarm
