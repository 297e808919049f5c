#pragma once
// Resident memory of this process, for the benchmarks' per-particle figures.

#include <cstddef>
#include <optional>

namespace swarmlab::scenarios {

/// Peak resident memory of this process since the last reset_peak_memory(), in bytes; none
/// where the operating system does not tell (anything but Linux, and WebAssembly).
std::optional<std::size_t> peak_memory();
std::optional<std::size_t> current_memory();
void reset_peak_memory();

}  // namespace swarmlab::scenarios
