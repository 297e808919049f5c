#pragma once
/// What a run will do: the engine, the time step, how long, how often to sample, and the
/// paper's stepwise expansion of the container if there is one.

#include <optional>

#include "swarm/engine/engine.h"

namespace swarm {

/// The container radius grows by `factor` every `tau`; within each stage the first
/// thermalize_fraction of tau is left alone and P, T are averaged over the rest.
struct ExpansionProtocol {
  double factor = 1.1;
  long stages = 10;
  double tau = 1.0;
  double thermalize_fraction = 0.8;
};

struct RunPlan {
  EngineConfig engine;
  double dt = 1e-3;
  long steps = 1000;  ///< for expansions: stages * steps_per_stage
  long sample_every = 1;
  std::optional<ExpansionProtocol> expansion;
  /// Outside a protocol's stages, keep every step's wall tally (24 bytes a step) so that
  /// Run::expand_now can close a stage by hand averaged like a protocol's. The UI's runs do;
  /// the CLI's have no hand to expand them.
  bool stages_by_hand = false;
};

/// Steps per expansion stage: round(tau / dt).
long steps_per_stage(const ExpansionProtocol& e, double dt);

}  // namespace swarm
