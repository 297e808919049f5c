#pragma once
// The fast engine's lookahead: exact predicted positions at the ends of the next few steps,
// valid as long as the centre-of-mass kicks stay within a budget.

#include <array>
#include <cmath>
#include <cstddef>

#include "engine/fast_engine_anchor.h"
#include "engine/timing_wheel.h"
#include "swarm/methods/external_forces.h"

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

  /// The flows over 0, 1, ..., kSteps + 1 steps: the CM's advance to each step end ahead, and
  /// the step's own flow.
  using FlowsAhead = std::array<ForcedFlow, kSteps + 2>;

  /// The flow and the predicted offset at the ends of this step and the kSteps after it.
  /// step_end: the flow at this step's end; flows: over whole steps (FlowsAhead); omega =
  /// sqrt|k|; R: the wall's radius; floor_z: the floor's height (-infinity: none).
  void prepare(const SharedMotion& motion, const ForcedFlow& step_end, const FlowsAhead& flows,
               double omega, double R, double floor_z) {
    const ForcedFlow& step = flows[1];
    // How far the offset at those step ends can move away from the prediction, given the kick
    // budget: each kick kappa moves V_cm and Y' alike, so the offset by kappa (cm_v(u) -
    // xs(u)), u the time since the kick.
    const ForcedFlow& span = flows[kSteps + 1];
    const double kick_drift = std::abs(span.cm_v - span.xs);
    ForcedFlow f = step_end;
    for (int j = 0; j <= kSteps; ++j) {
      ahead_[std::size_t(j)] = {f.xc, f.xs, motion.offset_at(f, flows[std::size_t(j) + 1])};
      // The flow over tau + dt is the step's flow after the flow over tau.
      ForcedFlow next = f;
      next.xc = step.xc * f.xc + step.xs * f.vc;
      next.xs = step.xc * f.xs + step.xs * f.vs;
      next.vc = step.vc * f.xc + step.vs * f.vc;
      next.vs = step.vc * f.xs + step.vs * f.vs;
      f = next;
    }
    const double slack = kKickBudget * omega * R * kick_drift + 1e-12 * R;
    limit2_ = (R - slack) * (R - slack);
    floor_limit_ = floor_z + slack;
  }

  /// The first step from `from` to `last` (now <= from, last <= now + kSteps) at whose end
  /// the oscillation y = xc a + xs b can be outside the wall or below the floor, or last + 1.
  StepIndex first_reach(const Vec3& a, const Vec3& b, StepIndex from, StepIndex last,
                        StepIndex now) const {
    for (StepIndex m = from; m <= last; ++m) {
      const Ahead& x = ahead_[std::size_t(m - now)];
      const Vec3 r = x.c * a + x.s * b + x.offset;
      if (r.squaredNorm() >= limit2_ || r.z() <= floor_limit_) return m;
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
  double floor_limit_ = 0;  // the floor's height plus slack
  std::array<double, kSteps + 1> recent_kicks_{};
};

}  // namespace swarm::fast
