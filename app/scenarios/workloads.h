#pragma once
// The workloads that the benchmarks, `swarmlab bench` and the tests share: the paper's
// expansion presets scaled to N particles.

#include "swarm/preset/preset.h"

namespace swarmlab::scenarios {

/// The attractive expansion of fig2-attractive-expansion.json (J > 0) or the repulsive
/// fireball of fig3-repulsive-fireball.json (J < 0), built in code with the same fields,
/// with N particles and J scaled by 4000 / N so that omega = sqrt(|J| M) stays close to 1.
swarm::Preset expansion_preset(bool repulsive, long particles);

/// The same preset with N particles and J rescaled to keep omega (for presets read from file).
swarm::Preset scaled(swarm::Preset preset, long particles);

}  // namespace swarmlab::scenarios
