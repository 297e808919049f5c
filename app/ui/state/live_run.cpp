#include "ui/state/live_run.h"

#include <algorithm>
#include <cmath>

#include "swarm/physics/regime.h"

namespace swarmlab {
namespace {

constexpr std::size_t kTrailPoints = 600;

/// The preset's plan, with stages by hand: "Expand now" ends a stage averaged like the
/// protocol's; threads > 0 sets the engine's thread count.
swarm::RunPlan plan_of(const swarm::Preset& preset, int threads) {
  swarm::RunPlan plan = swarm::run_plan(preset);
  plan.stages_by_hand = true;
  if (threads > 0) plan.engine.threads = threads;
  return plan;
}

/// The timeline's snapshots may take this much memory: less in the browser (school
/// Chromebooks).
swarm::TimelineLimits timeline_limits_here() {
  swarm::TimelineLimits limits;
#ifdef __EMSCRIPTEN__
  limits.snapshot_bytes = 96e6;
#endif
  return limits;
}

}  // namespace

LiveRun::LiveRun(const swarm::Preset& preset, int threads)
    : preset_(preset),
      timeline_(swarm::initial_system(preset), plan_of(preset, threads), preset.compare,
                timeline_limits_here()) {
  static long runs_made = 0;
  id_ = ++runs_made;
  // About 150 trail points per period (or per the same time when J <= 0).
  const double time_scale = swarm::natural_time_of(swarm::stiffness(system()));
  const double period = std::isfinite(time_scale) ? time_scale : 2 * M_PI;
  trail_stride_ = std::max(1L, std::lround(period / 150.0 / preset.dt));
}

long LiveRun::advance(long steps) {
  long taken = 0;
  // One step at a time, so that the trails get their points between steps.
  while (taken < steps && timeline_.advance(1) == 1) {
    if (++steps_since_trail_point_ >= trail_stride_) record_trails();
    ++taken;
  }
  return taken;
}

void LiveRun::jump_towards(long target) {
  const long before = timeline_.step();
  timeline_.jump_towards(target);
  if (timeline_.step() == before) return;
  for (Trail& trail : trails_) trail.points.clear();
  record_trails();
}

void LiveRun::follow(const std::vector<std::size_t>& particles) {
  std::vector<Trail> kept;
  const std::size_t n = system().particles.size();
  for (std::size_t i : particles) {
    if (i >= n) continue;
    auto old = std::find_if(trails_.begin(), trails_.end(),
                            [i](const Trail& t) { return t.particle == i; });
    kept.push_back(old != trails_.end() ? std::move(*old) : Trail{i, {}});
  }
  trails_ = std::move(kept);
  record_trails();
}

void LiveRun::record_trails() {
  steps_since_trail_point_ = 0;
  const swarm::System& s = system();
  for (Trail& trail : trails_) {
    const swarm::Vec3& r = s.particles[trail.particle].r;
    const Eigen::Vector3f point = r.cast<float>();
    if (!trail.points.empty() && trail.points.back() == point) continue;
    trail.points.push_back(point);
    if (trail.points.size() > kTrailPoints) trail.points.pop_front();
  }
}

}  // namespace swarmlab
