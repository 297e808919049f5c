#include "swarm/physics/analytic.h"

#include <cmath>

#include "math/portable_math.h"
#include "swarm/physics/flow.h"
#include "swarm/physics/regime.h"

namespace swarm {

AnalyticSolution::AnalyticSolution(const System& initial)
    : initial_(initial),
      k_(stiffness(initial)),
      cm_position0_(swarm::cm_position(initial)),
      cm_velocity_(swarm::cm_velocity(initial)) {
  x0_.reserve(initial.particles.size());
  u0_.reserve(initial.particles.size());
  for (const auto& p : initial.particles) {
    x0_.push_back(p.r - cm_position0_);
    u0_.push_back(p.v - cm_velocity_);
  }
}

Vec3 AnalyticSolution::cm_position_at(double t) const {
  return cm_position0_ + cm_velocity_ * (t - initial_.t);
}

Particle AnalyticSolution::particle_at(std::size_t i, double t) const {
  const Flow f = Flow::over(k_, t - initial_.t);
  Particle p = initial_.particles[i];
  p.r = cm_position_at(t) + f.c * x0_[i] + f.s * u0_[i];
  p.v = cm_velocity_ + f.dc() * x0_[i] + f.c * u0_[i];
  return p;
}

System AnalyticSolution::at(double t) const {
  System s = initial_;
  s.t = t;
  const Flow f = Flow::over(k_, t - initial_.t);
  const Vec3 R = cm_position_at(t);
  for (std::size_t i = 0; i < s.particles.size(); ++i) {
    s.particles[i].r = R + f.c * x0_[i] + f.s * u0_[i];
    s.particles[i].v = cm_velocity_ + f.dc() * x0_[i] + f.c * u0_[i];
  }
  return s;
}

double AnalyticSolution::omega() const { return omega_of(k_); }
double AnalyticSolution::period() const { return period_of(k_); }

OrbitParameters AnalyticSolution::orbit(std::size_t i) const {
  OrbitParameters o;
  const double w = omega();
  switch (regime_of(k_)) {
    case Regime::attractive:
      o.A = x0_[i];
      o.B = u0_[i] / w;
      break;
    case Regime::repulsive:
      o.C = 0.5 * (x0_[i] + u0_[i] / w);
      o.D = 0.5 * (x0_[i] - u0_[i] / w);
      break;
    case Regime::free:
      o.A = x0_[i];
      o.B = u0_[i];
      break;
  }
  return o;
}

OrbitEllipse AnalyticSolution::ellipse(std::size_t i) const {
  if (regime_of(k_) == Regime::attractive) {
    const OrbitParameters o = orbit(i);
    return ellipse_of(o.A, o.B);
  }
  return {x0_[i], u0_[i]};
}

OrbitEllipse ellipse_of(const Vec3& A, const Vec3& B) {
  // |A cos + B sin|^2 is extremal where tan(2 theta) = 2 A.B / (|A|^2 - |B|^2).
  const double theta = 0.5 * portable::atan2(2 * A.dot(B), A.squaredNorm() - B.squaredNorm());
  double sin_theta, cos_theta;
  portable::sincos(theta, &sin_theta, &cos_theta);
  const Vec3 p = A * cos_theta + B * sin_theta;
  const Vec3 q = -A * sin_theta + B * cos_theta;
  if (p.squaredNorm() >= q.squaredNorm()) return {p, q};
  return {q, p};
}

}  // namespace swarm
