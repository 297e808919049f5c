#pragma once
// The wall windows of many particles at once: the fast engine computes those of a step's hits
// and of an expired anchor's particles together, four at a time in AVX2 registers where the
// CPU has them (J < 0: four particles; off-centre J > 0: four points of one particle's grid),
// and gets the same bits as window_of and off_centre_window_of one by one.

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

/// out[j] = off_centre_window_of(a[j], b[j], w, spring, T2, phase_origin) for j < n, to the
/// last bit: where the CPU has AVX2, each window's grid of the turn four points at a time
/// (off_centre_window_of_avx2), the particles one after another (the expiry of an anchor
/// re-windows about 31,000 under gravity at N = 40,000, a step's hits a few dozen).
void off_centre_windows_of(const Vec3* a, const Vec3* b, std::size_t n, const Vec3& w,
                           const Spring& spring, double T2, double phase_origin, Window* out);

/// Whether windows_of runs four windows at once on this machine (for the benchmarks).
bool windows_use_avx2();

}  // namespace swarm::fast
