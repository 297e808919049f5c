#pragma once
/// The initial conditions of one run of an ensemble: independent runs of one preset differ
/// only in the seed their starting state is drawn from.

#include <cstdint>
#include <string>

#include "swarm/preset/preset.h"

namespace swarm {

/// The seed of run `index` of an ensemble with master seed `master`: a counter-based hash
/// (splitmix64 of the pair), so run k is the same whichever machine or order runs it, and
/// runs k and k + 1 are as unrelated as any two seeds. 53 bits, as a preset's seed may hold.
std::uint64_t run_seed(std::uint64_t master, std::uint64_t index);

/// The preset as run `seed` of an ensemble starts it, or why it cannot.
struct SeededPreset {
  std::optional<Preset> preset;
  std::string error;  ///< names the field and the rule, as a preset's errors do
};

/// A generated swarm draws its particles from `seed` (particles.seed). Listed particles
/// stay as listed unless `perturbation` > 0: then each particle's position moves by up to
/// perturbation times the swarm's rms distance from its CM, and its velocity by up to
/// perturbation times its rms speed about the CM velocity (each uniform in a ball, drawn from
/// `seed`); without a perturbation listed particles are refused, since every run would be
/// the same. A perturbed particle that leaves the container or goes below the floor is
/// refused with the preset's own message.
SeededPreset with_seed(const Preset& p, std::uint64_t seed, double perturbation);

}  // namespace swarm
