#pragma once
// Whether this build carries the engine's AVX2 paths: x86-64 with GCC or Clang, not wasm. They
// are compiled with target("avx2") and taken only on a CPU that has it (cpu_has_avx2 in
// engine/fast_engine_window_batch.cpp); wasm and other CPUs take the scalar paths, which give
// the same bits.
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__)) && !defined(__EMSCRIPTEN__)
#define SWARM_AVX2_BUILD 1
#include <immintrin.h>
#endif
