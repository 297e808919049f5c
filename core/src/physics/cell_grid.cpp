#include "physics/cell_grid.h"

#include <algorithm>
#include <cmath>

namespace swarm {

void CellGrid::build(const std::vector<Particle>& particles, double min_side) {
  const std::size_t N = particles.size();
  Vec3 lo = Vec3::Constant(0), hi = Vec3::Constant(0);
  if (N > 0) lo = hi = particles[0].r;
  for (const Particle& p : particles) lo = lo.cwiseMin(p.r), hi = hi.cwiseMax(p.r);
  const double extent = (hi - lo).maxCoeff();
  // No more cells per side than the smallest c with c^3 >= 2 N, whatever the extent (counted,
  // not std::cbrt, whose last bit differs between C libraries and would change the cells).
  double cap = 1;
  while (cap * cap * cap < 2.0 * double(N)) cap += 1;
  n_ = int(std::clamp(std::floor(extent / min_side), 1.0, cap));
  const double side = std::max(extent / n_, min_side);
  const std::size_t cells = std::size_t(n_) * n_ * n_;

  start_.assign(cells + 1, 0);
  cell_.resize(N);
  order_.resize(N);
  for (std::size_t i = 0; i < N; ++i) {
    int k[3];
    for (int a = 0; a < 3; ++a)
      k[a] = std::min(n_ - 1, int((particles[i].r[a] - lo[a]) / side));
    cell_[i] = std::uint32_t((k[2] * n_ + k[1]) * n_ + k[0]);
    ++start_[cell_[i] + 1];
  }
  for (std::size_t c = 0; c < cells; ++c) start_[c + 1] += start_[c];
  // By cell, and by index within a cell.
  fill_.assign(start_.begin(), start_.end() - 1);
  for (std::size_t i = 0; i < N; ++i) order_[fill_[cell_[i]]++] = std::uint32_t(i);
}

}  // namespace swarm
