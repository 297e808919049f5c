#pragma once
/// A fingerprint of a system's state, to check cheaply that two builds (native and
/// WebAssembly, or two versions) computed the same run to the last bit.

#include <cstdint>

#include "swarm/physics/system.h"

namespace swarm {

/// FNV-1a (64-bit) over the bit patterns of J, t, the particle count and then every
/// particle's m, r and v in order. Bits, not values: -0.0 and 0.0 hash differently on
/// purpose, since IEEE 754 arithmetic defines the sign of zero and a build that flips it has
/// computed something else (NaNs, whose payload the platforms do not agree on, never occur in
/// a valid state).
std::uint64_t state_hash(const System& s);

}  // namespace swarm
