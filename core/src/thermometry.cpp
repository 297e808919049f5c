#include "swarm/thermometry.h"

namespace swarm {

void WallMeter::add(const WallTally& step_tally, double dt, double R) {
  hits_ += step_tally.hits;
  if (step_tally.hits > 0) impulse_per_area_ += step_tally.radial_impulse / sphere_area(R);
  hit_kinetic_energy_ += step_tally.hit_kinetic_energy;
  elapsed_ += dt;
}

WallReading WallMeter::reading() const {
  WallReading w;
  w.hits = hits_;
  if (elapsed_ > 0) w.P = impulse_per_area_ / elapsed_;
  if (hits_ > 0) w.T = 0.5 * hit_kinetic_energy_ / double(hits_);
  return w;
}

void WallMeter::reset() { *this = WallMeter{}; }

}  // namespace swarm
