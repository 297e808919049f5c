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

double WallPath::lowest_between(double t0, double t1) const {
  // The radius is linear between the legs' ends, so its least value is at t0, t1 or an end.
  double lowest = std::min(radius_at(t0), radius_at(t1));
  for (const double t : starts_)
    if (t0 < t && t < t1) lowest = std::min(lowest, radius_at(t));
  return lowest;
}

void reflect_off_moving_wall(Particle& p, double u, WallTally& tally) {
  p.v += moving_wall_reflection(p.m, p.r, p.v, u, tally);
}

}  // namespace swarm
