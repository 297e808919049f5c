#pragma once
// The workloads the benchmarks and `swarmlab bench` share: the paper's expansion presets
// scaled to N particles, and peak-memory readings.

#include <cstddef>
#include <optional>

#include "swarm/preset.h"

namespace swarm::bench {

/// The attractive expansion of fig2-attractive-expansion.json (J > 0) or the repulsive
/// fireball of fig3-repulsive-fireball.json (J < 0), built in code with the same fields,
/// with N particles and J scaled by 4000 / N so that omega = sqrt(|J| M) stays close to 1.
Preset expansion_preset(bool repulsive, long particles);

/// The same preset with N particles and J rescaled to keep omega (for presets read from file).
Preset scaled(Preset preset, long particles);

/// Peak resident memory of this process since the last reset_peak_memory(), in bytes; none
/// where the operating system does not tell (anything but Linux, and WebAssembly).
std::optional<std::size_t> peak_memory();
std::optional<std::size_t> current_memory();
void reset_peak_memory();

}  // namespace swarm::bench
