#pragma once
/// The exact path ahead of any particle of an isolated system, cheap enough to draw every
/// frame: the centre of mass and k = J M are taken once (O(N)), then each path costs O(points).
/// AnalyticSolution answers the same question but copies the whole system.

#include <vector>

#include "swarm/physics/system.h"

namespace swarm {

class OrbitsAhead {
 public:
  /// Reads the centre of mass and the stiffness of s at its current time: O(N).
  explicit OrbitsAhead(const System& s);

  /// Lab-frame positions of particle p (a particle of the system given to the constructor)
  /// at points + 1 evenly spaced instants from now to now + span (time): the orbit about the
  /// uniformly moving centre of mass, an ellipse for J > 0 (eq. 7), the runaway for J < 0
  /// (eq. 15), a straight line for J = 0.
  std::vector<Vec3> path(const Particle& p, double span, int points) const;

  double stiffness() const { return k_; }  ///< k = J M (1/time^2)
  const Vec3& cm_velocity() const { return cm_velocity_; }

 private:
  Vec3 cm_position_, cm_velocity_;
  double k_ = 0;
};

}  // namespace swarm
