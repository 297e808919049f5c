#include "engine/fast_engine_lookahead.h"

#include "math/avx2.h"

namespace swarm::fast {

#ifdef SWARM_AVX2_BUILD

bool Lookahead::uses_avx2() { return cpu_has_avx2(); }

// target("avx2") without "fma": the compiler cannot fuse a multiply and an add, so each lane
// rounds as first_reach_one_by_one does.
__attribute__((target("avx2"))) std::size_t Lookahead::first_reach_avx2(
    const Ahead& t, const Vec3& a, const Vec3& b, std::size_t from, std::size_t last) {
  const __m256d ax = _mm256_set1_pd(a.x()), ay = _mm256_set1_pd(a.y()),
                az = _mm256_set1_pd(a.z());
  const __m256d bx = _mm256_set1_pd(b.x()), by = _mm256_set1_pd(b.y()),
                bz = _mm256_set1_pd(b.z());
  const __m256d limit2 = _mm256_set1_pd(t.limit2), floor_limit = _mm256_set1_pd(t.floor_limit);
  // Rows are padded to kRow, a multiple of 4, and last < kSteps + 1 <= kRow: a group that
  // starts at or before last ends inside the row.
  for (std::size_t j = from; j <= last; j += 4) {
    const __m256d c = _mm256_loadu_pd(t.c + j), s = _mm256_loadu_pd(t.s + j);
    const __m256d x =
        _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(c, ax), _mm256_mul_pd(s, bx)),
                      _mm256_loadu_pd(t.x + j));
    const __m256d y =
        _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(c, ay), _mm256_mul_pd(s, by)),
                      _mm256_loadu_pd(t.y + j));
    const __m256d z =
        _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(c, az), _mm256_mul_pd(s, bz)),
                      _mm256_loadu_pd(t.z + j));
    const __m256d r2 = _mm256_add_pd(
        _mm256_mul_pd(x, x), _mm256_add_pd(_mm256_mul_pd(y, y), _mm256_mul_pd(z, z)));
    const int reached = _mm256_movemask_pd(_mm256_or_pd(_mm256_cmp_pd(r2, limit2, _CMP_GE_OQ),
                                                        _mm256_cmp_pd(z, floor_limit, _CMP_LE_OQ)));
    if (reached) {
      // Lanes past `last` are the padding or steps not asked about; the first lane reached
      // decides, since every lane before it did not reach.
      const std::size_t first = j + std::size_t(__builtin_ctz(unsigned(reached)));
      return first <= last ? first : last + 1;
    }
  }
  return last + 1;
}

#else

bool Lookahead::uses_avx2() { return false; }

std::size_t Lookahead::first_reach_avx2(const Ahead& t, const Vec3& a, const Vec3& b,
                                        std::size_t from, std::size_t last) {
  return first_reach_one_by_one(t, a, b, from, last);
}

#endif

}  // namespace swarm::fast
