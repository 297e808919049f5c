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
    for (std::size_t j = 0; j <= std::size_t(kSteps); ++j) {
      const Vec3 offset = motion.offset_at(f, flows[j + 1]);
      ahead_.c[j] = f.xc;
      ahead_.s[j] = f.xs;
      ahead_.x[j] = offset.x();
      ahead_.y[j] = offset.y();
      ahead_.z[j] = offset.z();
      // The flow over tau + dt is the step's flow after the flow over tau.
      ForcedFlow next = f;
      next.xc = step.xc * f.xc + step.xs * f.vc;
      next.xs = step.xc * f.xs + step.xs * f.vs;
      next.vc = step.vc * f.xc + step.vs * f.vc;
      next.vs = step.vc * f.xs + step.vs * f.vs;
      f = next;
    }
    const double slack = kKickBudget * omega * R * kick_drift + 1e-12 * R;
    ahead_.limit2 = (R - slack) * (R - slack);
    ahead_.floor_limit = floor_z + slack;
  }

  /// The first step from `from` to `last` (now <= from, last <= now + kSteps) at whose end
  /// the oscillation y = xc a + xs b can be outside the wall or below the floor, or last + 1.
  /// Four steps at a time in AVX2 where the CPU has it, with the same operations, so the same
  /// step, as one by one.
  StepIndex first_reach(const Vec3& a, const Vec3& b, StepIndex from, StepIndex last,
                        StepIndex now) const {
    if (last < from) return last + 1;
    const std::size_t begin = std::size_t(from - now), end = std::size_t(last - now);
    return now + StepIndex(use_avx2_ ? first_reach_avx2(ahead_, a, b, begin, end)
                                     : first_reach_one_by_one(ahead_, a, b, begin, end));
  }

  /// first_reach without AVX2 (the browser's, and the yardstick of the AVX2 path's tests).
  StepIndex first_reach_one_by_one(const Vec3& a, const Vec3& b, StepIndex from, StepIndex last,
                                   StepIndex now) const {
    if (last < from) return last + 1;
    return now + StepIndex(first_reach_one_by_one(ahead_, a, b, std::size_t(from - now),
                                                  std::size_t(last - now)));
  }

  /// Whether first_reach runs four steps at once on this machine.
  static bool uses_avx2();

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
  /// Flow values and the predicted shared offset (x, y, z) at the ends of the next few steps,
  /// a row each, padded to whole AVX2 registers (the padding is read, never taken).
  static constexpr std::size_t kRow = (kSteps + 1 + 3) / 4 * 4;
  struct Ahead {
    alignas(32) double c[kRow] = {}, s[kRow] = {}, x[kRow] = {}, y[kRow] = {}, z[kRow] = {};
    double limit2 = 0;  // (R - slack)^2: the kicks within budget move |r| less than slack
    double floor_limit = 0;  // the floor's height plus slack
  };

  /// The first index from `from` to `last` whose predicted position reaches a limit, or
  /// last + 1: r = (c a + s b) + offset component by component, |r|^2 = x^2 + (y^2 + z^2)
  /// (Eigen's order), no fused multiply-add.
  static std::size_t first_reach_one_by_one(const Ahead& t, const Vec3& a, const Vec3& b,
                                            std::size_t from, std::size_t last) {
    for (std::size_t j = from; j <= last; ++j) {
      const double x = t.c[j] * a.x() + t.s[j] * b.x() + t.x[j];
      const double y = t.c[j] * a.y() + t.s[j] * b.y() + t.y[j];
      const double z = t.c[j] * a.z() + t.s[j] * b.z() + t.z[j];
      if (x * x + (y * y + z * z) >= t.limit2 || z <= t.floor_limit) return j;
    }
    return last + 1;
  }
  static std::size_t first_reach_avx2(const Ahead& t, const Vec3& a, const Vec3& b,
                                      std::size_t from, std::size_t last);

  Ahead ahead_;
  bool use_avx2_ = uses_avx2();
  std::array<double, kSteps + 1> recent_kicks_{};
};

}  // namespace swarm::fast
