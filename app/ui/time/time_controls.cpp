#include "ui/time/time_controls.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "i18n/printed.h"
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

/// Ends the travel under way; the page hears how its seek ended.
void end_travel(AppState& state, bool reached) {
  const TimeTravel& travel = state.travel;
  if (travel.kind == TimeTravel::Kind::to_time) state.travel_ends.push_back({travel.id, state.run->time(), reached});
  if (travel.kind != TimeTravel::Kind::seek && reached) state.last_fast_forward.reached = true;
  state.travel = {};
}

}  // namespace

long travel_to(AppState& state, TimeTravel::Kind kind, long target) {
  const swarm::Timeline& timeline = state.run->timeline();
  target = std::clamp(target, 0L, timeline.end_step());
  const long chunk = state.travel.active() ? state.travel.chunk : 1;
  if (state.travel.active()) end_travel(state, false);  // overtaken
  state.run->jump_towards(target);
  state.travel = {kind, ++state.travels_started, state.run->step(), target, chunk};
  state.playing = false;
  state.step_debt = 0;
  if (kind != TimeTravel::Kind::seek) state.last_fast_forward = {kind, 0, {}, false};
  const long id = state.travel.id;
  if (state.run->step() == target) end_travel(state, true);
  return id;
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

void cancel_travel(AppState& state) {
  if (state.travel.active()) end_travel(state, false);
}

void continue_travel(AppState& state, double budget_ms) {
  using clock = std::chrono::steady_clock;
  TimeTravel& travel = state.travel;
  if (!travel.active()) return;
  LiveRun& run = *state.run;
  const clock::time_point start = clock::now();
  run.jump_towards(travel.target);
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
  if (travel.kind != TimeTravel::Kind::seek)
    state.last_fast_forward.longest_ms = std::max(state.last_fast_forward.longest_ms, spent_ms);
  if (run.step() >= travel.target || run.finished()) end_travel(state, run.step() >= travel.target);
}

void play_or_continue(AppState& state) {
  cancel_travel(state);
  if (!state.playing && state.run->finished() && state.run->primary().failure().empty())
    state.run->extend(swarm::run_plan(state.preset).steps);
  state.playing = !state.playing;
}

std::string seek_refusal(const AppState& state, double t) {
  const swarm::Timeline& timeline = state.run->timeline();
  const double end = double(timeline.end_step()) * state.preset.dt;
  // Half a step of slack either side: t is rounded to a step.
  if (std::isfinite(t) && t >= -0.5 * state.preset.dt && t <= end + 0.5 * state.preset.dt) return {};
  return printed("t = %.10g is beyond the run: t must be from 0 to the end of the preset's run, "
                 "t = %.10g",
                 t, end);
}

long seek_in_frames(AppState& state, double t) {
  return travel_to(state, TimeTravel::Kind::to_time, state.run->timeline().step_of(t));
}

}  // namespace swarmlab
