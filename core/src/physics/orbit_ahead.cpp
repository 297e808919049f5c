#include "swarm/physics/orbit_ahead.h"

#include "swarm/physics/flow.h"

namespace swarm {

OrbitsAhead::OrbitsAhead(const System& s)
    : cm_position_(swarm::cm_position(s)),
      cm_velocity_(swarm::cm_velocity(s)),
      k_(swarm::stiffness(s)) {}

std::vector<Vec3> OrbitsAhead::path(const Particle& p, double span, int points) const {
  const Vec3 x = p.r - cm_position_, u = p.v - cm_velocity_;
  std::vector<Vec3> out;
  out.reserve(std::size_t(points) + 1);
  for (int step = 0; step <= points; ++step) {
    const double tau = points > 0 ? span * step / points : 0.0;
    const Flow f = Flow::over(k_, tau);
    out.push_back(cm_position_ + cm_velocity_ * tau + f.c * x + f.s * u);
  }
  return out;
}

}  // namespace swarm
