#pragma once
// Moving the run in time from the window: play, seeks (the timeline strip, step back, the JS
// API) and fast-forwards ("to the end of this stage", "to the end of the run"). The core's
// swarm::Timeline does the work: it re-simulates from its snapshots, so every state is the
// first pass's.

#include "ui/app_state.h"

namespace swarmlab {

/// Starts moving to `target` (clamped to the run's steps); play pauses.
void travel_to(AppState& state, TimeTravel::Kind kind, long target);
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
/// Moves the run to time t at once (the JS API); returns the time reached.
double seek_now(AppState& state, double t);

}  // namespace swarmlab
