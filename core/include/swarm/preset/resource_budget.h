#pragma once
/// What a preset will cost, estimated from the preset alone before anything is allocated, and
/// the limits a front end sets on it: the CLI's generous ones (this project's 24 GB, 2-core
/// machine, a run of up to about two hours) and the browser's (a school Chromebook: about 1 GB, and
/// steps short enough to draw frames).

#include <string>

namespace swarm {

struct Preset;

/// Limits on one run. Defaults: the CLI and the desktop app.
struct ResourceLimits {
  double memory_bytes = 12e9;  ///< half of this 24 GB machine
  /// particles x steps, summed over the runs side by side: 2e12 took an hour here (2e6
  /// particles in a container at 5.4e8 a second, the machine busy), so 4e12 is about two.
  double particle_steps = 4e12;
  /// pairs x force evaluations x steps of the pairwise methods (1.6e9 a second measured).
  double pair_evaluations = 4e12;
  /// pairs x force evaluations in one step: how long the slowest step may take (here: the
  /// preset rules' 20,000 particles for every method).
  double pair_evaluations_per_step = 1e9;
};

/// A school Chromebook's browser tab: about 1 GB of memory, a pairwise step within about a
/// tenth of a second in wasm, and a run to the end in minutes.
ResourceLimits browser_limits();

struct ResourceEstimate {
  double particles = 0;  ///< N
  double steps = 0;
  double runs = 1;              ///< the primary method and every compared one
  double samples = 0;           ///< samples each run keeps
  double particle_bytes = 0;    ///< particle state of every run and the initial copy
  double sample_bytes = 0;      ///< samples (and comparison samples) of every run
  double output_bytes = 0;      ///< files built in memory before they are written
  double particle_steps = 0;    ///< N x steps x runs, weighted by the cost of the features (gravity, a floor, drag, hard spheres; an inelastic floor's reference engine)
  double pair_evaluations = 0;  ///< N (N - 1) / 2 x force evaluations x steps, pairwise runs
  double pair_evaluations_per_step = 0;
  double memory_bytes() const { return particle_bytes + sample_bytes + output_bytes; }
};

/// The cost of running p to the end; with_output_files adds RESULT.json, the CSV and the
/// figures, which the CLI builds whole in memory before writing them.
ResourceEstimate estimate_resources(const Preset& p, bool with_output_files = false);

/// "" when p fits within limits, else one line naming the field that drives the cost, the
/// estimate and the limit, e.g. "sample_every: 1e+09 samples need ~128 GB of memory (limit
/// 12 GB); raise sample_every".
std::string resource_error(const Preset& p, const ResourceLimits& limits,
                           bool with_output_files = false);

}  // namespace swarm
