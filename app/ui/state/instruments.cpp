#include "ui/state/instruments.h"

#include <algorithm>
#include <cmath>

#include "swarm/physics/system.h"

namespace swarmlab {
namespace {

/// The particle tracks keep at most this many frames; the older half goes when it is full.
constexpr std::size_t kTrackPoints = 20000;

void update_track(Instruments& in, LiveRun& run, std::optional<std::size_t> selected) {
  if (!selected) {
    in.track.reset();
    return;
  }
  const swarm::System& s = run.system();
  const std::size_t i = *selected;
  if (i >= s.particles.size()) {
    in.track.reset();
    return;
  }
  const double t = run.time();
  if (!in.track || in.track->particle != i || in.track->run != run.id() ||
      t < in.track->last_t) {
    in.track.emplace();
    in.track->particle = i;
    in.track->run = run.id();
    in.track->meter = swarm::PeriodMeter(swarm::stiffness(s));
  } else if (t == in.track->last_t && !in.track->t.empty()) {
    return;  // paused: nothing new to see
  }
  ParticleTrack& track = *in.track;
  const swarm::Vec3 x = s.particles[i].r - swarm::cm_position(s);
  const swarm::Vec3 u = s.particles[i].v - swarm::cm_velocity(s);
  track.meter.add(t, x, u);
  if (track.t.empty()) track.x_start = x.x();
  if (track.t.size() >= kTrackPoints) {
    track.t.erase(track.t.begin(), track.t.begin() + kTrackPoints / 2);
    track.x.erase(track.x.begin(), track.x.begin() + kTrackPoints / 2);
  }
  track.t.push_back(t);
  track.x.push_back(x.x());
  track.last_t = t;
}

void update_wall(Instruments& in, LiveRun& run, double average_window) {
  const auto& samples = run.primary().samples();
  if (in.wall_run == run.id() && in.wall_samples == samples.size() &&
      in.wall_window == average_window)
    return;
  in.wall_run = run.id();
  in.wall_samples = samples.size();
  in.wall_window = average_window;
  in.wall = swarm::wall_estimate(swarm::wall_intervals(samples), average_window);
  in.virial.reset();
  if (in.wall.intervals == 0 || !swarm::virial_balance_applies(run.primary().plan().engine))
    return;
  const double from = samples.back().t - in.wall.window;
  // The sample at the window's start: the balance of this window alone, at the cost of its
  // own samples.
  const auto first = std::lower_bound(samples.begin(), samples.end(), from,
                                      [](const swarm::Sample& s, double t) {
                                        return s.t < t - 1e-9 * std::max(1.0, std::abs(t));
                                      });
  if (first != samples.end())
    in.virial = swarm::virial_balance(
        swarm::virial_intervals(samples, std::size_t(first - samples.begin())), from);
}

}  // namespace

std::optional<double> shown_wall_error(double value, const std::optional<double>& error,
                                       swarm::WallErrorSource source) {
  if (!error || source == swarm::WallErrorSource::none) return std::nullopt;
  if (source == swarm::WallErrorSource::parts && !(*error < std::abs(value))) return std::nullopt;
  return error;
}

void Instruments::update(LiveRun& run, std::optional<std::size_t> selected,
                         double average_window, bool container) {
  stopwatch.observe(run.time());
  update_track(*this, run, selected);
  if (container) update_wall(*this, run, average_window);
}

}  // namespace swarmlab
