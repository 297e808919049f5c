#pragma once
/// The exact one-dimensional flow of every particle's motion about the centre of mass.

namespace swarm {

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
