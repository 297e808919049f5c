#pragma once
/// The three kinds of motion about the centre of mass and their exact one-dimensional flow.

namespace swarm {

enum class Regime { attractive, free, repulsive };

/// Classifies k = J M: oscillation (k > 0), free flight (k = 0), exponential runaway (k < 0).
Regime regime_of(double k);

/// sqrt(|k|) (1/time): the angular frequency omega = sqrt(J M) for J > 0, the runaway rate
/// Omega = sqrt(-J M) for J < 0, 0 for J = 0.
double omega_of(double k);

/// Period 2 pi / omega of the attractive case; infinity otherwise.
double period_of(double k);

/// The exact flow of x'' = -k x over a time t: x(t) = c x0 + s v0, v(t) = -k s x0 + c v0.
/// c = cos(omega t), s = sin(omega t)/omega for k > 0; cosh and sinh/Omega for k < 0;
/// c = 1, s = t for k = 0. The map has determinant 1, which is why it conserves energy.
struct Flow {
  double c = 1.0;
  double s = 0.0;
  double k = 0.0;

  static Flow over(double k, double t);
  /// dv/dx0: the velocity's dependence on the initial displacement.
  double dc() const { return -k * s; }
};

}  // namespace swarm
