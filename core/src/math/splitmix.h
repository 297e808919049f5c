#pragma once
// SplitMix64 (Steele, Lea and Flood, OOPSLA 2014) as a counter-based generator: the n-th number
// is a function of n alone, so draws keyed on (step, particle) or (seed, run) are the same
// whichever order, thread or machine asks for them.

#include <cstdint>

namespace swarm {

/// SplitMix64's finaliser: a bijection of 64 bits whose outputs pass BigCrush as a counter
/// generator.
inline std::uint64_t splitmix64_mix(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

/// SplitMix64's golden-ratio increment, 2^64 / phi, odd.
inline constexpr std::uint64_t kSplitmix64Gamma = 0x9e3779b97f4a7c15ULL;

/// The generator's output for the state x: its finaliser of x + gamma.
inline std::uint64_t splitmix64(std::uint64_t x) { return splitmix64_mix(x + kSplitmix64Gamma); }

}  // namespace swarm
