#pragma once
/// Linear drag (Appendix B): either mass-proportional, a force -gamma m_i v_i on every particle,
/// which keeps the centre-of-mass picture (the CM velocity decays as exp(-gamma t) and every
/// particle is a damped oscillator about the CM), or a force -b v_i on chosen particles only,
/// which breaks it and needs a numerical method.

#include <cstddef>
#include <vector>

#include "swarm/physics/system.h"

namespace swarm {

struct Drag {
  double gamma = 0;  ///< mass-proportional drag rate, 1/time: force -gamma m_i v_i on every particle
  double b = 0;      ///< drag coefficient, mass/time: force -b v_i on the listed particles
  std::vector<std::size_t> particles;  ///< the particles b acts on (indices)

  /// Whether the drag acts on every particle in proportion to its mass (the analytic case).
  bool mass_proportional() const { return b == 0; }
};

/// The drag rate c_i (1/time) of every particle: dv_i/dt gains -c_i v_i. gamma for all, or
/// b / m_i for the listed particles and 0 for the rest.
std::vector<double> drag_rates(const Drag& drag, const System& s);

/// The power the drag takes from the particles, sum c_i m_i |v_i|^2 >= 0 (energy/time).
double drag_power(const std::vector<double>& rates, const System& s);

}  // namespace swarm
