#pragma once
/// The state of an N-body system under the linear force law F = -J m1 m2 r.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

namespace swarm {

using Vec3 = Eigen::Vector3d;

/// One point mass. Units are the paper's base units: mass, length and time are
/// dimensionless, so J carries 1/(mass time^2).
struct Particle {
  double m = 1.0;         ///< mass, > 0
  Vec3 r = Vec3::Zero();  ///< position in the lab frame
  Vec3 v = Vec3::Zero();  ///< velocity in the lab frame
};

/// N particles coupled pairwise with strength J (J > 0 attractive, J < 0 repulsive).
struct System {
  double J = 1.0;
  double t = 0.0;  ///< simulated time
  std::vector<Particle> particles;
};

double total_mass(const System& s);
Vec3 cm_position(const System& s);
Vec3 cm_velocity(const System& s);

/// k = J M (1/time^2): the spring constant per unit mass that ties every particle to the CM,
/// omega^2 when attractive and -Omega^2 when repulsive.
double stiffness(const System& s);

}  // namespace swarm
