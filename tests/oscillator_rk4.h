#pragma once
// The one-dimensional motion x'' = -k x integrated numerically, written in the tests so that
// the exact flow and the rates of the core are checked against a calculation of their own.

namespace swarm::testing {

/// Advances (x, v) by a time t (may be negative) with `steps` classic RK4 steps of x'' = -k x.
inline void integrate_oscillator(double k, double t, int steps, double& x, double& v) {
  const double h = t / steps;
  for (int i = 0; i < steps; ++i) {
    const double x1 = v, v1 = -k * x;
    const double x2 = v + 0.5 * h * v1, v2 = -k * (x + 0.5 * h * x1);
    const double x3 = v + 0.5 * h * v2, v3 = -k * (x + 0.5 * h * x2);
    const double x4 = v + h * v3, v4 = -k * (x + h * x3);
    x += h / 6 * (x1 + 2 * x2 + 2 * x3 + x4);
    v += h / 6 * (v1 + 2 * v2 + 2 * v3 + v4);
  }
}

}  // namespace swarm::testing
