#pragma once
// Moving the run in time from the window: play, seeks (the timeline strip, step back, the JS
// API) and fast-forwards ("to the end of this stage", "to the end of the run"). The core's
// swarm::Timeline does the work: it re-simulates from its snapshots, so every state is the
// first pass's.

#include <string>

#include "ui/state/app_state.h"

namespace swarmlab {

/// Starts moving to `target` (clamped to the run's steps); play pauses, a travel under way
/// ends (overtaken). Returns the new travel's id (it may have ended at once, at its target).
long travel_to(AppState& state, TimeTravel::Kind kind, long target);
/// One step back (and, with coarse, 1/100 of a period or of the run's length).
void step_back(AppState& state, bool coarse);
/// 1/100 of a period forward.
void step_forward_coarse(AppState& state);
void fast_forward_to_stage_end(AppState& state);
void fast_forward_to_run_end(AppState& state);
void cancel_travel(AppState& state);
/// Carries the travel under way on for about budget_ms; ends it at its target.
void continue_travel(AppState& state, double budget_ms);
/// Play / pause; a finished run continues by another run length rather than doing nothing.
void play_or_continue(AppState& state);
/// Why the page may not seek to time t: "" when t is within the run (0 to the end of the
/// preset's run, or of its continuation), else one sentence naming t and the rule.
std::string seek_refusal(const AppState& state, double t);
/// The page's seek (the JS API): starts moving to time t (rounded to a step) in per-frame
/// budgets like a fast-forward, its progress shown as one; returns the travel's id, whose end
/// state.travel_ends records. Check seek_refusal first.
long seek_in_frames(AppState& state, double t);

}  // namespace swarmlab
