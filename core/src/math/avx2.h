#pragma once
// Whether this build carries the engine's AVX2 paths: x86-64 with GCC or Clang, not wasm. They
// are compiled with target("avx2") and taken only where cpu_has_avx2(); wasm and other CPUs
// take the scalar paths, which give the same bits.
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__)) && !defined(__EMSCRIPTEN__)
#define SWARM_AVX2_BUILD 1
#include <immintrin.h>

namespace swarm {
/// Whether this CPU has AVX2 (asked once).
inline bool cpu_has_avx2() {
  static const bool has = __builtin_cpu_supports("avx2");
  return has;
}
}  // namespace swarm
#endif
