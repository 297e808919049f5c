#pragma once
// Closed-form wall windows of a free oscillator, used by the fast engine's scheduler.

#include "swarm/system.h"

namespace swarm::fast {

/// The earliest tau >= tau_from at which |h(tau)| >= sqrt(T2), where h(tau) = a c(tau) +
/// b s(tau) is the free flow of x'' = -k x (Flow::over(k, tau)); +infinity if never.
/// J > 0: |h|^2 is a constant plus a sinusoid in 2 omega tau; J < 0: a quadratic in
/// exp(2 Omega tau); J = 0: a quadratic in tau.
double window_entry(const Vec3& a, const Vec3& b, double k, double tau_from, double T2);

}  // namespace swarm::fast
