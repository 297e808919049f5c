#pragma once
// Whether every number a preset's run computes stays a finite double: the quantities derived
// from the preset (M, omega, the energies at t = 0, their largest growth over the run, the
// container's radius and volume, the wall pressure) are bounded from above before the run and
// must stay below kLargestDerived.

#include <string>

#include "swarm/preset/preset.h"

namespace swarm {

/// 1e300 leaves eight orders of magnitude below the largest double (1.8e308) for the sums over
/// up to 1e7 particles and the order-one factors the bounds leave out.
inline constexpr double kLargestDerived = 1e300;
/// The container's radius stays in [1e-100, 1e100], so V = 4/3 pi R^3 and R^2 stay normal
/// doubles within [1e-300, 1e300].
inline constexpr double kSmallestRadius = 1e-100, kLargestRadius = 1e100;

/// "" when every derived number of p's run stays finite with that margin, else
/// "field: rule (got ...)" naming the field to change.
std::string unrepresentable_numbers(const Preset& p);

}  // namespace swarm
