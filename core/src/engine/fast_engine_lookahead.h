#pragma once
// The fast engine's lookahead: exact predicted positions at the ends of the next few steps,
// valid as long as the centre-of-mass kicks stay within a budget.

#include <array>
#include <cmath>
#include <cstddef>

#include "engine/fast_engine_anchor.h"
#include "engine/timing_wheel.h"
#include "swarm/physics/flow.h"

namespace swarm::fast {

/// Once a particle's wall window is less than kSteps steps away, its predicted lab positions
/// at the next step ends are checked one by one, so that it is checked again only in a step in
/// which it can actually hit. The predictions use the state before this step's hits; they
/// assume that the kicks of any kSteps + 1 consecutive steps sum to at most kKickBudget *
/// sqrt|k| * R in size, which the engine checks with kicks_within_budget().
class Lookahead {
 public:
  static constexpr int kSteps = 16;
  static constexpr double kKickBudget = 0.2;

  /// The flow and the predicted offset at the ends of this step and the kSteps after it.
  /// step_end: the flow at this step's end; omega = sqrt|k|; R: the wall's radius.
  void prepare(const SharedMotion& motion, const Flow& step_end, double k, double omega, double dt,
               double R) {
    if (dt != dt_) {
      // How far the offset at those step ends can move away from the prediction, given the
      // kick budget: each kick kappa moves it by kappa (u - s(u)), u the time since the kick.
      dt_ = dt;
      step_flow_ = Flow::over(k, dt);
      const double u = (kSteps + 1) * dt;
      kick_drift_ = std::abs(u - Flow::over(k, u).s);
    }
    const Flow& step_flow = step_flow_;
    Flow f = step_end;
    for (int j = 0; j <= kSteps; ++j) {
      ahead_[std::size_t(j)] = {f.c, f.s, motion.offset_at(f, (j + 1) * dt)};
      // c(tau + dt) = c c_dt - k s s_dt, s(tau + dt) = s c_dt + c s_dt (addition theorems).
      const double c = f.c * step_flow.c - k * f.s * step_flow.s;
      const double s = f.s * step_flow.c + f.c * step_flow.s;
      f.c = c;
      f.s = s;
    }
    const double slack = kKickBudget * omega * R * kick_drift_ + 1e-12 * R;
    limit2_ = (R - slack) * (R - slack);
  }

  /// The first step from `from` to `last` (now <= from, last <= now + kSteps) at whose end
  /// the oscillation y = c a + s b can be outside the wall, or last + 1.
  StepIndex first_reach(const Vec3& a, const Vec3& b, StepIndex from, StepIndex last,
                        StepIndex now) const {
    for (StepIndex m = from; m <= last; ++m) {
      const Ahead& x = ahead_[std::size_t(m - now)];
      if ((x.c * a + x.s * b + x.offset).squaredNorm() >= limit2_) return m;
    }
    return last + 1;
  }

  /// Records the size of the kick (the change of V_cm) of step `step`.
  void record_kick(StepIndex step, double kick) {
    recent_kicks_[std::size_t(step) % recent_kicks_.size()] = kick;
  }
  /// Whether the kicks of the last kSteps + 1 steps stayed within budget.
  bool kicks_within_budget(double omega, double R) const {
    double sum = 0;
    for (double kick : recent_kicks_) sum += kick;
    return sum <= kKickBudget * omega * R;
  }
  void forget_kicks() { recent_kicks_.fill(0); }

 private:
  /// Flow values and the predicted shared offset at the end of one of the next few steps.
  struct Ahead {
    double c, s;
    Vec3 offset;
  };

  std::array<Ahead, kSteps + 1> ahead_{};
  double limit2_ = 0;  // (R - slack)^2: the kicks within budget move |r| less than slack
  double dt_ = 0, kick_drift_ = 0;
  Flow step_flow_;
  std::array<double, kSteps + 1> recent_kicks_{};
};

}  // namespace swarm::fast
