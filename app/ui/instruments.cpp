#include "instruments.h"

#include "app_state.h"
#include "swarm/system.h"

namespace swarmlab {
namespace {

/// The particle tracks keep at most this many frames; the older half goes when it is full.
constexpr std::size_t kTrackPoints = 20000;

void update_track(AppState& state) {
  Instruments& in = state.instruments;
  if (!state.selected) {
    in.track.reset();
    return;
  }
  const swarm::System& s = state.run->system();
  const std::size_t i = *state.selected;
  if (i >= s.particles.size()) {
    in.track.reset();
    return;
  }
  const double t = state.run->time();
  if (!in.track || in.track->particle != i || in.track->run != state.run->id() ||
      t < in.track->last_t) {
    in.track.emplace();
    in.track->particle = i;
    in.track->run = state.run->id();
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

void update_wall(AppState& state) {
  Instruments& in = state.instruments;
  const auto& samples = state.run->primary().samples();
  if (in.wall_run == state.run->id() && in.wall_samples == samples.size() &&
      in.wall_window == state.plots.average_window)
    return;
  in.wall_run = state.run->id();
  in.wall_samples = samples.size();
  in.wall_window = state.plots.average_window;
  in.wall = swarm::wall_estimate(swarm::wall_intervals(samples), state.plots.average_window);
}

}  // namespace

void update_instruments(AppState& state) {
  state.instruments.stopwatch.observe(state.run->time());
  update_track(state);
  if (state.preset.container_radius) update_wall(state);
}

bool select_particle(AppState& state, std::optional<std::size_t> index) {
  if (index && *index >= state.run->system().particles.size()) return false;
  state.selected = index;
  state.update_followed();
  return true;
}

}  // namespace swarmlab
