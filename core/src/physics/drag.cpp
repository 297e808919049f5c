#include "swarm/physics/drag.h"

namespace swarm {

std::vector<double> drag_rates(const Drag& drag, const System& s) {
  std::vector<double> c(s.particles.size(), drag.mass_proportional() ? drag.gamma : 0.0);
  if (!drag.mass_proportional())
    for (std::size_t i : drag.particles)
      if (i < c.size()) c[i] = drag.b / s.particles[i].m;
  return c;
}

double drag_power(const std::vector<double>& rates, const System& s) {
  double p = 0;
  for (std::size_t i = 0; i < s.particles.size(); ++i)
    p += rates[i] * s.particles[i].m * s.particles[i].v.squaredNorm();
  return p;
}

}  // namespace swarm
