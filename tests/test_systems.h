#pragma once
// Small systems the tests share, built by hand so that expected values follow from the
// equations rather than from the code under test.

#include "swarm/initial_conditions.h"
#include "swarm/system.h"

namespace swarm::testing {

/// The four masses of the paper's Fig. 1 (0.25, 0.5, 1, 1.5) at its drawn positions, with
/// velocities chosen by hand so the orbits are genuinely three-dimensional.
inline System four_masses(double J = 1.0) {
  System s;
  s.J = J;
  s.particles = {{0.25, {0, -1, 0}, {0.3, 0.1, 0.2}},
                 {0.5, {5, 0, 0}, {-0.2, 0.4, 0}},
                 {1.0, {4, 3, 0}, {0.1, -0.3, -0.1}},
                 {1.5, {-1, 4, 0.5}, {0, 0.1, 0.05}}};
  return s;
}

inline System random_swarm(long n, double J, std::uint64_t seed, double radius = 1.0,
                           double speed = 1.0) {
  SwarmSpec spec;
  spec.count = n;
  spec.mass_min = 4;
  spec.mass_max = 5;
  spec.position_radius = radius;
  spec.speed = speed;
  spec.seed = seed;
  System s = generate_swarm(spec);
  s.J = J;
  return s;
}

}  // namespace swarm::testing
