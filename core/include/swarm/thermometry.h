#pragma once
/// Pressure and temperature measured at the container wall (paper section III.A).
/// Convention (k_B = 1): P = sum |dp_r| / (4 pi R^2 t_interval), and T is half the mean
/// kinetic energy of the particles that hit the wall in the interval. Particles reach the
/// wall at a rate proportional to their speed, so for an ideal gas the hitters' mean kinetic
/// energy is 2T: with this convention T equals the ideal-gas temperature and P V = N T holds
/// when J = 0.

#include <cstdint>
#include "swarm/wall.h"

namespace swarm {

struct WallReading {
  double P = 0;  ///< pressure, force per area
  double T = 0;  ///< temperature, energy units; 0 when nothing hit the wall
  std::int64_t hits = 0;
};

/// Accumulates the wall tallies of consecutive steps.
class WallMeter {
 public:
  /// R is the container radius during the step: the pressure divides by its area.
  void add(const WallTally& step_tally, double dt, double R);
  WallReading reading() const;
  void reset();

 private:
  std::int64_t hits_ = 0;
  double impulse_per_area_ = 0;
  double hit_kinetic_energy_ = 0;
  double elapsed_ = 0;  // time covered by the tallies added: P divides by it
};

}  // namespace swarm
