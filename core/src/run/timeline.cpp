#include "swarm/run/timeline.h"

#include <algorithm>
#include <cmath>

namespace swarm {
namespace {

constexpr double kSnapshotBytesPerParticle = 256;  // a run's share: engine, copies, schedule
constexpr std::size_t kMinSnapshots = 4;

}  // namespace

Timeline::Timeline(const System& initial, const RunPlan& plan,
                   const std::vector<Method>& compared, const TimelineLimits& limits)
    : present_(std::make_unique<SideBySide>(initial, plan, compared)),
      t0_(initial.t),
      dt_(plan.dt) {
  const double per_snapshot = std::max(1.0, double(initial.particles.size())) *
                              double(1 + compared.size()) * kSnapshotBytesPerParticle;
  max_snapshots_ = std::clamp(std::size_t(limits.snapshot_bytes / per_snapshot), kMinSnapshots,
                              std::max(kMinSnapshots, limits.max_snapshots));
  interval_ = std::max(1L, (plan.steps + long(max_snapshots_) - 1) / long(max_snapshots_));
  take_snapshot();
}

long Timeline::end_step() const {
  long end = present_->primary().plan().steps;
  for (const TimelineAction& a : actions_)
    if (a.kind == TimelineAction::Kind::extend && a.step > step()) end += long(a.amount);
  return end;
}

long Timeline::advance(long n) {
  long taken = 0;
  while (taken < n && !present_->finished()) {
    present_->advance(1);
    ++taken;
    const long s = step();
    for (const TimelineAction& a : actions_)
      if (a.step == s) apply(a);
    reached_ = std::max(reached_, s);
    if (s >= snapshots_.back().step + interval_) take_snapshot();
  }
  return taken;
}

void Timeline::jump_towards(long target) {
  auto after = std::upper_bound(snapshots_.begin(), snapshots_.end(), target,
                                [](long t, const Snapshot& s) { return t < s.step; });
  if (after == snapshots_.begin()) return;
  const Snapshot& latest = *(after - 1);
  if (target < step() || latest.step > step())
    present_ = std::make_unique<SideBySide>(*latest.runs);
}

long Timeline::seek(long target) {
  target = std::clamp(target, 0L, end_step());
  jump_towards(target);
  advance(target - step());
  return step();
}

long Timeline::step_of(double t) const {
  // Clamped as a double: long is 32 bits in wasm.
  const double steps = std::round((t - t0_) / dt_);
  return steps > 0 ? long(std::min(steps, double(end_step()))) : 0L;
}

void Timeline::apply(const TimelineAction& a) {
  if (a.kind == TimelineAction::Kind::expand)
    present_->scale_container(a.amount);
  else
    present_->extend(long(a.amount));
}

void Timeline::forget_after_present() {
  const long s = step();
  while (!snapshots_.empty() && snapshots_.back().step >= s) snapshots_.pop_back();
  actions_.erase(std::remove_if(actions_.begin(), actions_.end(),
                                [s](const TimelineAction& a) { return a.step > s; }),
                 actions_.end());
  reached_ = s;
}

void Timeline::expand_now(double factor) {
  forget_after_present();
  actions_.push_back({step(), TimelineAction::Kind::expand, factor});
  apply(actions_.back());
  take_snapshot();
}

void Timeline::extend(long steps) {
  forget_after_present();
  actions_.push_back({step(), TimelineAction::Kind::extend, double(steps)});
  apply(actions_.back());
  take_snapshot();
}

void Timeline::take_snapshot() {
  snapshots_.push_back({step(), std::make_unique<SideBySide>(*present_)});
  if (snapshots_.size() <= max_snapshots_) return;
  // Thin: keep every other snapshot, the start's among them, and space the next ones wider.
  std::vector<Snapshot> kept;
  for (std::size_t i = 0; i < snapshots_.size(); i += 2) kept.push_back(std::move(snapshots_[i]));
  snapshots_ = std::move(kept);
  interval_ *= 2;
}

std::vector<long> Timeline::stage_starts() const {
  std::vector<long> starts{0};
  const RunPlan& plan = present_->primary().plan();
  if (plan.expansion) {
    const long per_stage = steps_per_stage(*plan.expansion, plan.dt);
    for (long k = 1; k <= plan.expansion->stages; ++k) starts.push_back(k * per_stage);
  }
  for (const TimelineAction& a : actions_)
    if (a.kind == TimelineAction::Kind::expand) starts.push_back(a.step);
  std::sort(starts.begin(), starts.end());
  starts.erase(std::unique(starts.begin(), starts.end()), starts.end());
  return starts;
}

long Timeline::end_of_stage() const {
  const RunPlan& plan = present_->primary().plan();
  const long s = step();
  if (plan.expansion) {
    const long per_stage = steps_per_stage(*plan.expansion, plan.dt);
    if (s < plan.expansion->stages * per_stage) return (s / per_stage + 1) * per_stage;
  }
  for (const TimelineAction& a : actions_)
    if (a.kind == TimelineAction::Kind::expand && a.step > s) return a.step;
  return end_step();
}

}  // namespace swarm
