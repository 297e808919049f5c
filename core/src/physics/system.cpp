#include "swarm/physics/system.h"

namespace swarm {

double total_mass(const System& s) {
  double M = 0;
  for (const auto& p : s.particles) M += p.m;
  return M;
}

Vec3 cm_position(const System& s) {
  Vec3 sum = Vec3::Zero();
  for (const auto& p : s.particles) sum += p.m * p.r;
  return sum / total_mass(s);
}

Vec3 cm_velocity(const System& s) {
  Vec3 sum = Vec3::Zero();
  for (const auto& p : s.particles) sum += p.m * p.v;
  return sum / total_mass(s);
}

double stiffness(const System& s) { return s.J * total_mass(s); }

}  // namespace swarm
