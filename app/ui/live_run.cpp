#include "live_run.h"

#include <algorithm>
#include <cmath>

#include "swarm/diagnostics.h"
#include "swarm/regime.h"
#include "swarm/side_by_side.h"

namespace swarmlab {
namespace {

constexpr std::size_t kTrailPoints = 600;

}  // namespace

LiveRun::LiveRun(const swarm::Preset& preset) : preset_(preset) {
  static long runs_made = 0;
  id_ = ++runs_made;
  const swarm::System initial = swarm::initial_system(preset);
  const swarm::RunPlan plan = swarm::run_plan(preset);
  primary_ = std::make_unique<swarm::Run>(initial, plan);
  for (swarm::Method m : preset.compare) {
    swarm::RunPlan other = plan;
    other.engine.method = m;
    compared_.push_back(std::make_unique<swarm::Run>(initial, other));
  }

  // The exact solution to measure against: the primary itself, or a compared analytic run.
  swarm::Run* exact = preset.method == swarm::Method::analytic ? primary_.get() : nullptr;
  for (std::size_t i = 0; i < compared_.size() && !exact; ++i)
    if (preset.compare[i] == swarm::Method::analytic) exact = compared_[i].get();
  if (exact && exact != primary_.get()) analytic_reference_ = exact;
  if (exact) {
    if (preset.method != swarm::Method::analytic) errors_.push_back({preset.method, {}, {}});
    for (swarm::Method m : preset.compare)
      if (m != swarm::Method::analytic) errors_.push_back({m, {}, {}});
  }
  record_errors();

  const double k = swarm::stiffness(initial);
  const double rate = swarm::omega_of(k);
  const double period = rate > 0 ? 2 * M_PI / rate : 2 * M_PI;
  trail_stride_ = std::max(1L, std::lround(period / 150.0 / preset.dt));
}

long LiveRun::advance(long steps) {
  long taken = 0;
  // One step at a time in lockstep, so that the errors are taken at the primary's samples.
  while (taken < steps && !finished()) {
    const std::size_t before = primary_->samples().size();
    primary_->advance(1);
    for (auto& run : compared_) run->advance(1);
    if (primary_->samples().size() != before) record_errors();
    if (++steps_since_trail_point_ >= trail_stride_) record_trails();
    ++taken;
  }
  return taken;
}

void LiveRun::record_errors() {
  if (errors_.empty()) return;
  swarm::Run& exact = analytic_reference_ ? *analytic_reference_ : *primary_;
  const swarm::System& reference = exact.engine().system();
  std::size_t track = 0;
  // Energy errors need no track: the Compare tab reads them from each run's samples.
  auto add = [&](swarm::Run& run) {
    ErrorTrack& e = errors_[track++];
    const swarm::System& s = run.engine().system();
    e.t.push_back(s.t);
    e.position_error.push_back(swarm::max_position_difference(s, reference));
  };
  if (preset_.method != swarm::Method::analytic) add(*primary_);
  for (std::size_t i = 0; i < compared_.size(); ++i)
    if (preset_.compare[i] != swarm::Method::analytic) add(*compared_[i]);
}

void LiveRun::expand_container(double factor) {
  auto grow = [factor](swarm::Run& run) {
    if (const auto R = run.engine().container_radius())
      run.engine().set_container_radius(*R * factor);
  };
  grow(*primary_);
  for (auto& run : compared_) grow(*run);
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
