#include "ui/time/time_controls.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "swarm/physics/regime.h"

namespace swarmlab {
namespace {

/// 1/100 of a period (J > 0), of the e-folding or free-flight time scale, or, when nothing
/// sets a time scale, of the run's planned length: at least one step.
long coarse_steps(AppState& state) {
  const double time_scale = swarm::natural_time_of(swarm::stiffness(state.run->system()));
  const double length = std::isfinite(time_scale) ? time_scale
                                                  : double(state.run->timeline().end_step()) *
                                                        state.preset.dt;
  return std::max(1L, std::lround(length / 100 / state.preset.dt));
}

}  // namespace

void travel_to(AppState& state, TimeTravel::Kind kind, long target) {
  const swarm::Timeline& timeline = state.run->timeline();
  target = std::clamp(target, 0L, timeline.end_step());
  state.run->jump_towards(target);
  const long chunk = state.travel.active() ? state.travel.chunk : 1;
  state.travel = {kind, state.run->step(), target, chunk};
  state.playing = false;
  state.step_debt = 0;
  if (kind != TimeTravel::Kind::seek) state.last_fast_forward = {kind, 0, {}, false};
  if (state.run->step() == target) {
    state.travel = {};
    if (kind != TimeTravel::Kind::seek) state.last_fast_forward.reached = true;
  }
}

void step_back(AppState& state, bool coarse) {
  travel_to(state, TimeTravel::Kind::seek,
            state.run->step() - (coarse ? coarse_steps(state) : 1));
}

void step_forward_coarse(AppState& state) {
  travel_to(state, TimeTravel::Kind::seek, state.run->step() + coarse_steps(state));
}

void fast_forward_to_stage_end(AppState& state) {
  travel_to(state, TimeTravel::Kind::to_stage_end, state.run->timeline().end_of_stage());
}

void fast_forward_to_run_end(AppState& state) {
  travel_to(state, TimeTravel::Kind::to_run_end, state.run->timeline().end_step());
}

void cancel_travel(AppState& state) { state.travel = {}; }

void continue_travel(AppState& state, double budget_ms) {
  using clock = std::chrono::steady_clock;
  TimeTravel& travel = state.travel;
  if (!travel.active()) return;
  LiveRun& run = *state.run;
  run.jump_towards(travel.target);
  const clock::time_point start = clock::now();
  double spent_ms = 0;
  while (run.step() < travel.target && !run.finished() && spent_ms < budget_ms) {
    const clock::time_point chunk_start = clock::now();
    if (run.advance(std::min(travel.chunk, travel.target - run.step())) == 0) break;
    const double chunk_ms =
        std::chrono::duration<double, std::milli>(clock::now() - chunk_start).count();
    // Chunks of a few milliseconds: the clock is read rarely, the budget overrun is small.
    if (chunk_ms < 2)
      travel.chunk *= 2;
    else if (chunk_ms > 8 && travel.chunk > 1)
      travel.chunk /= 2;
    spent_ms = std::chrono::duration<double, std::milli>(clock::now() - start).count();
  }
  if (run.step() >= travel.target || run.finished()) {
    if (travel.kind != TimeTravel::Kind::seek && run.step() >= travel.target)
      state.last_fast_forward.reached = true;
    travel = {};
  }
}

void play_or_continue(AppState& state) {
  cancel_travel(state);
  if (!state.playing && state.run->finished() && state.run->primary().failure().empty())
    state.run->extend(swarm::run_plan(state.preset).steps);
  state.playing = !state.playing;
}

double seek_now(AppState& state, double t) {
  const long target = state.run->timeline().step_of(t);
  cancel_travel(state);
  state.playing = false;
  state.run->jump_towards(target);
  state.run->advance(target - state.run->step());
  return state.run->time();
}

}  // namespace swarmlab
