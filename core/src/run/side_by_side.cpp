#include "swarm/run/side_by_side.h"

#include <algorithm>

#include "run/advance_to_end.h"
#include "swarm/physics/diagnostics.h"

namespace swarm {

double max_position_difference(const System& a, const System& b) {
  double worst = 0;
  const std::size_t n = std::min(a.particles.size(), b.particles.size());
  for (std::size_t i = 0; i < n; ++i)
    worst = std::max(worst, (a.particles[i].r - b.particles[i].r).norm());
  return worst;
}

SideBySide::SideBySide(const System& initial, const RunPlan& plan,
                       const std::vector<Method>& compared)
    : primary_(std::make_unique<Run>(initial, plan)) {
  for (Method m : compared) {
    RunPlan other = plan;
    other.engine.method = m;
    tracks_.push_back({m, std::make_unique<Run>(initial, other), {}});
  }
  if (plan.engine.method == Method::analytic) exact_ = primary_.get();
  for (std::size_t i = 0; i < tracks_.size() && !exact_; ++i)
    if (tracks_[i].method == Method::analytic) exact_ = tracks_[i].run.get();
  if (exact_) {
    if (plan.engine.method != Method::analytic) errors_.push_back({plan.engine.method, {}, {}});
    for (Method m : compared)
      if (m != Method::analytic) errors_.push_back({m, {}, {}});
  }
  record();
}

SideBySide::SideBySide(const SideBySide& other)
    : primary_(std::make_unique<Run>(*other.primary_)), errors_(other.errors_) {
  if (other.exact_ == other.primary_.get()) exact_ = primary_.get();
  for (const Track& track : other.tracks_) {
    tracks_.push_back({track.method, std::make_unique<Run>(*track.run), track.samples});
    if (other.exact_ == track.run.get()) exact_ = tracks_.back().run.get();
  }
}

void SideBySide::record() {
  const System& reference = primary_->engine().system();
  for (Track& track : tracks_) {
    const System& s = track.run->engine().system();
    track.samples.push_back({s.t, total_energy(s), max_position_difference(s, reference)});
  }
  if (!exact_) return;
  const System& exact = exact_->engine().system();
  auto next = errors_.begin();
  auto add = [&](Run& run) {
    const System& s = run.engine().system();
    next->t.push_back(s.t);
    next->position_error.push_back(max_position_difference(s, exact));
    ++next;
  };
  if (primary_->plan().engine.method != Method::analytic) add(*primary_);
  for (Track& track : tracks_)
    if (track.method != Method::analytic) add(*track.run);
}

void SideBySide::scale_container(double factor) {
  primary_->expand_now(factor);
  for (Track& track : tracks_) track.run->expand_now(factor);
}

void SideBySide::extend(long steps) {
  primary_->extend(steps);
  for (Track& track : tracks_) track.run->extend(steps);
}

long SideBySide::advance(long n) {
  long taken = 0;
  while (taken < n && !finished()) {
    const std::size_t before = primary_->samples().size();
    primary_->advance(1);
    for (Track& track : tracks_) track.run->advance(1);
    if (primary_->samples().size() != before) record();
    ++taken;
  }
  return taken;
}

void SideBySide::finish(const std::function<void(double)>& progress) {
  const double total = double(primary_->plan().steps);
  advance_to_end([this](long n) { advance(n); }, [this] { return finished(); },
                 [this, total] { return double(primary_->steps_done()) / total; }, progress);
}

bool SideBySide::finished() const { return primary_->finished() || !failure().empty(); }

std::string SideBySide::failure() const {
  if (!primary_->failure().empty()) return primary_->failure();
  for (const Track& track : tracks_)
    if (!track.run->failure().empty())
      return std::string(name_of(track.method)) + ": " + track.run->failure();
  return {};
}

}  // namespace swarm
