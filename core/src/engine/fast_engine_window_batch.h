#pragma once
// The wall windows of many particles at once: the fast engine computes those of a step's hits
// together, four at a time in AVX2 registers where the CPU has them (J < 0), and gets the
// same bits as window_of one by one.

#include <cstddef>

#include "engine/fast_engine_window.h"

namespace swarm::fast {

/// out[j] = window_of(a[j], b[j], spring, T2, phase_origin) for j < n, to the last bit: the
/// vector path performs window_of's operations in its order (IEEE-exact +, -, *, / and sqrt,
/// no fused multiply-add), and leaves every case off the common path (never, always, only
/// the decaying part, a logarithm of a subnormal or infinite number) to window_of itself.
/// The schedule, and so the order in which a step's kicks are summed, is then the same on
/// every machine and in wasm (which takes the scalar path).
void windows_of(const Vec3* a, const Vec3* b, std::size_t n, const Spring& spring, double T2,
                double phase_origin, Window* out);

/// Whether windows_of runs four windows at once on this machine (for the benchmarks).
bool windows_use_avx2();

}  // namespace swarm::fast
