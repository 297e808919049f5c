#include "swarm/physics/wall_motion.h"

#include <algorithm>
#include <cmath>

namespace swarm {

WallPath::WallPath(double R0, std::vector<WallMove> moves) : R0_(R0), moves_(std::move(moves)) {
  double t = 0, R = R0_;
  for (const WallMove& m : moves_) {
    starts_.push_back(t);
    t += std::abs(m.to - R) / m.speed;
    R = m.to;
  }
  starts_.push_back(t);  // the end of the last move
}

double WallPath::radius_at(double t) const {
  double R = R0_;
  for (std::size_t i = 0; i < moves_.size(); ++i) {
    const WallMove& m = moves_[i];
    if (t < starts_[i + 1]) {
      const double travelled = std::max(0.0, t - starts_[i]) * m.speed;
      return m.to > R ? R + travelled : R - travelled;
    }
    R = m.to;
  }
  return R;
}

double WallPath::end_time() const { return starts_.back(); }

void reflect_off_moving_wall(Particle& p, double u, WallTally& tally) {
  const Vec3 n = p.r.normalized();
  const double v_r = p.v.dot(n);
  const double kinetic_before = 0.5 * p.m * p.v.squaredNorm();
  const Vec3 dv = 2 * (u - v_r) * n;
  p.v += dv;
  tally.hits += 1;
  tally.radial_impulse += std::abs(2 * p.m * (v_r - u));
  tally.hit_kinetic_energy += kinetic_before;
  tally.wall_momentum -= p.m * dv;
  tally.books.wall_work += 0.5 * p.m * p.v.squaredNorm() - kinetic_before;
}

}  // namespace swarm
