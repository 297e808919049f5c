#pragma once
/// The paper's closed-form solution of an isolated system (eqs. 7 and 15).

#include <vector>

#include "swarm/physics/system.h"

namespace swarm {

/// The orbit of one particle about the centre of mass.
/// J > 0: x(t) = A cos(omega t) + B sin(omega t) (eq. 7);
/// J < 0: x(t) = C exp(Omega t) + D exp(-Omega t) (eq. 15);
/// J = 0: x(t) = A + B t. Times count from the solution's reference time t0.
struct OrbitParameters {
  Vec3 A = Vec3::Zero(), B = Vec3::Zero();
  Vec3 C = Vec3::Zero(), D = Vec3::Zero();
};

/// The closed ellipse an attractive orbit traces about the (moving) centre of mass.
struct OrbitEllipse {
  Vec3 semi_major = Vec3::Zero();  ///< from the centre to the farthest point
  Vec3 semi_minor = Vec3::Zero();  ///< perpendicular to semi_major, in the orbit plane
};

/// The state of an isolated system at any time, computed straight from t.
class AnalyticSolution {
 public:
  explicit AnalyticSolution(const System& initial);

  /// The exact system at time t (absolute time, same clock as System::t).
  System at(double t) const;
  /// Position and velocity of particle i at time t.
  Particle particle_at(std::size_t i, double t) const;

  double omega() const;   ///< omega or Omega, 0 when J = 0
  double period() const;  ///< 2 pi / omega for J > 0, infinity otherwise
  Vec3 cm_position_at(double t) const;
  Vec3 cm_velocity() const { return cm_velocity_; }

  OrbitParameters orbit(std::size_t i) const;
  /// Only meaningful for J > 0; for J <= 0 the path is open and both axes are returned as
  /// the directions of A and B.
  OrbitEllipse ellipse(std::size_t i) const;

 private:
  System initial_;
  double k_ = 0;
  Vec3 cm_position0_, cm_velocity_;
  std::vector<Vec3> x0_, u0_;  // positions and velocities relative to the CM at t0
};

/// The semi-axes of the ellipse A cos(theta) + B sin(theta).
OrbitEllipse ellipse_of(const Vec3& A, const Vec3& B);

}  // namespace swarm
