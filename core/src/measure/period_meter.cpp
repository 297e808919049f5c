#include "swarm/measure/period_meter.h"

#include <cmath>

#include "swarm/physics/regime.h"

namespace swarm {
namespace {

/// The cubic Hermite interpolant on [0, h] with p(0) = s0, p'(0) = g0, p(h) = s1, p'(h) = g1.
double hermite(double tau, double h, double s0, double g0, double s1, double g1) {
  const double a = tau / h, b = 1 - a;
  return s0 * b * b * (1 + 2 * a) + s1 * a * a * (1 + 2 * b) + h * a * b * (g0 * b - g1 * a);
}

/// A root of the interpolant in [0, h], where s0 and s1 have opposite signs (or s1 = 0), by
/// bisection: 60 halvings reach the rounding of h.
double crossing(double h, double s0, double g0, double s1, double g1) {
  double lo = 0, hi = h;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    const double p = hermite(mid, h, s0, g0, s1, g1);
    if ((p < 0) == (s0 < 0))
      lo = mid;
    else
      hi = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

PeriodMeter::PeriodMeter(double k) : k_(k) {
  if (regime_of(k) != Regime::attractive) status_ = PeriodStatus::no_period;
}

void PeriodMeter::add(double t, const Vec3& x, const Vec3& u) {
  if (status_ == PeriodStatus::no_period || status_ == PeriodStatus::at_centre) return;
  if (!start_) {
    // The initial displacement sets the direction; a particle starting on the CM is timed
    // along its velocity instead (its displacement grows along it).
    const Vec3& along = x.squaredNorm() > 0 ? x : u;
    if (along.squaredNorm() == 0) {
      status_ = PeriodStatus::at_centre;
      return;
    }
    start_ = t;
    direction_ = along.normalized();
    last_t_ = t;
    last_s_ = x.dot(direction_);
    last_slope_ = u.dot(direction_);
    return;
  }
  if (!(t > last_t_)) return;
  const double h = t - last_t_;
  const double s = x.dot(direction_), slope = u.dot(direction_);
  if (h > 0.25 * period_of(k_)) {
    ++gaps_;
    last_crossing_[0].reset();
    last_crossing_[1].reset();
  } else if ((last_s_ < 0) != (s < 0)) {
    // Half-open: a sample exactly on zero counts on the positive side, so one crossing is
    // never seen twice.
    cross(last_t_ + crossing(h, last_s_, last_slope_, s, slope), last_s_ < 0 ? 1 : 0);
  }
  last_t_ = t;
  last_s_ = s;
  last_slope_ = slope;
}

void PeriodMeter::cross(double t, int direction) {
  if (const std::optional<double>& previous = last_crossing_[direction]) {
    period_sum_ += t - *previous;
    ++count_;
    ++pairs_[direction];
    status_ = PeriodStatus::measured;
  }
  last_crossing_[direction] = t;
}

std::optional<double> PeriodMeter::period() const {
  if (count_ == 0) return std::nullopt;
  return period_sum_ / count_;
}

std::optional<double> PeriodMeter::formula_period() const {
  if (regime_of(k_) != Regime::attractive) return std::nullopt;
  return period_of(k_);
}

std::optional<double> PeriodMeter::relative_difference() const {
  const std::optional<double> measured = period(), formula = formula_period();
  if (!measured || !formula) return std::nullopt;
  return (*measured - *formula) / *formula;
}

}  // namespace swarm
