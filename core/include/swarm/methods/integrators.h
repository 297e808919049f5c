#pragma once
/// One step of each method on an isolated system. All share the signature
/// void(System&, double dt, int threads) so that any two can run side by side from one
/// initial state. threads (any count >= 1) is how many threads the pairwise forces may use; the
/// results do not depend on it.

#include <vector>

#include "swarm/methods/method.h"
#include "swarm/physics/system.h"

namespace swarm {

struct ExternalForces;  // swarm/methods/external_forces.h

/// a_i = -J sum_k m_k (r_i - r_k), summed over every pair (eq. 1, no centre-of-mass shortcut).
void pairwise_accelerations(const System& s, std::vector<Vec3>& a, int threads = 1);

/// The exact map of the paper over dt: every particle moves on its analytic orbit about the
/// centre of mass, which itself moves uniformly.
void step_analytic(System& s, double dt, int threads = 1);
/// x += v dt, then v += a(x_old) dt.
void step_euler(System& s, double dt, int threads = 1);
/// v += a dt, then x += v dt (the paper's Euler-Cromer).
void step_euler_cromer(System& s, double dt, int threads = 1);
/// Velocity Verlet (kick-drift-kick).
void step_verlet(System& s, double dt, int threads = 1);
/// Classical fourth-order Runge-Kutta.
void step_rk4(System& s, double dt, int threads = 1);

/// The numerical methods under external forces (gravity, drag): the same steps with the
/// forces added to the pairwise accelerations. Verlet's closing half kick treats the drag
/// implicitly (trapezoidal), which keeps it second order.
void step_euler(System& s, double dt, int threads, const ExternalForces& f);
void step_euler_cromer(System& s, double dt, int threads, const ExternalForces& f);
void step_verlet(System& s, double dt, int threads, const ExternalForces& f);
void step_rk4(System& s, double dt, int threads, const ExternalForces& f);

/// Dispatches to the step function of method m.
void step(Method m, System& s, double dt, int threads = 1);

}  // namespace swarm
