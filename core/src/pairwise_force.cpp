#include <vector>

#include "swarm/integrators.h"

namespace swarm {

void pairwise_accelerations(const System& s, std::vector<Vec3>& a) {
  const std::size_t n = s.particles.size();
  // Structure-of-arrays copies let the inner loop over partners vectorise.
  std::vector<double> x(n), y(n), z(n), m(n), ax(n, 0.0), ay(n, 0.0), az(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = s.particles[i].r.x();
    y[i] = s.particles[i].r.y();
    z[i] = s.particles[i].r.z();
    m[i] = s.particles[i].m;
  }
  // Each pair once: the force on k is minus the force on i (Newton's third law).
  for (std::size_t i = 0; i < n; ++i) {
    const double xi = x[i], yi = y[i], zi = z[i], mi = m[i];
    double sx = 0, sy = 0, sz = 0;
    for (std::size_t k = i + 1; k < n; ++k) {
      const double dx = xi - x[k], dy = yi - y[k], dz = zi - z[k];
      sx += m[k] * dx;
      sy += m[k] * dy;
      sz += m[k] * dz;
      ax[k] += mi * dx;
      ay[k] += mi * dy;
      az[k] += mi * dz;
    }
    ax[i] -= sx;
    ay[i] -= sy;
    az[i] -= sz;
  }
  a.resize(n);
  for (std::size_t i = 0; i < n; ++i) a[i] = s.J * Vec3(ax[i], ay[i], az[i]);
}

}  // namespace swarm
