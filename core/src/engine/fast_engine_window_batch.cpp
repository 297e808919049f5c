#include "engine/fast_engine_window_batch.h"

#include <algorithm>
#include <cstdint>
#include <limits>

#include "math/avx2.h"
#include "math/fast_math.h"

namespace swarm::fast {
namespace {

void windows_one_by_one(const Vec3* a, const Vec3* b, std::size_t n, const Spring& spring,
                        double T2, double phase_origin, Window* out) {
  for (std::size_t j = 0; j < n; ++j) out[j] = window_of(a[j], b[j], spring, T2, phase_origin);
}

#ifdef SWARM_AVX2_BUILD

#define SWARM_AVX2 __attribute__((target("avx2")))

/// Four doubles, one per particle, with the same operations as the scalar code's.
struct Lanes {
  __m256d x, y, z;
};

SWARM_AVX2 inline Lanes load(const Vec3* v) {
  return {_mm256_set_pd(v[3].x(), v[2].x(), v[1].x(), v[0].x()),
          _mm256_set_pd(v[3].y(), v[2].y(), v[1].y(), v[0].y()),
          _mm256_set_pd(v[3].z(), v[2].z(), v[1].z(), v[0].z())};
}

/// Eigen's u.dot(v) and squaredNorm() for 3-vectors, summed in its order: x + (y + z).
SWARM_AVX2 inline __m256d dot(const Lanes& u, const Lanes& v) {
  return _mm256_add_pd(_mm256_mul_pd(u.x, v.x),
                       _mm256_add_pd(_mm256_mul_pd(u.y, v.y), _mm256_mul_pd(u.z, v.z)));
}

/// fast_log of four numbers; `special` gains the lanes that fast_log leaves to std::log.
SWARM_AVX2 inline __m256d log4(__m256d x, __m256i& special) {
  const __m256i bits = _mm256_castpd_si256(x);
  const __m256i biased_exponent = _mm256_srli_epi64(bits, 52);  // with the sign bit
  special = _mm256_or_si256(special, _mm256_cmpeq_epi64(biased_exponent, _mm256_setzero_si256()));
  special =
      _mm256_or_si256(special, _mm256_cmpgt_epi64(biased_exponent, _mm256_set1_epi64x(0x7fe)));
  constexpr std::int64_t kSqrtHalfBits = 0x3fe6a09e667f3bcd;
  const __m256i relative = _mm256_sub_epi64(bits, _mm256_set1_epi64x(kSqrtHalfBits));
  // The arithmetic shift of relative by 52 (AVX2 has only logical 64-bit shifts): |e| < 1024
  // for the finite positive x that reach here, so e + 1024 is shifted logically instead.
  const __m256i e_biased = _mm256_srli_epi64(
      _mm256_add_epi64(relative, _mm256_set1_epi64x(std::int64_t(1024) << 52)), 52);
  // e as a double, exactly: 1.5 * 2^52 + (e + 1024) has those bits; take 1.5 * 2^52 + 1024.
  const __m256d e = _mm256_sub_pd(
      _mm256_castsi256_pd(_mm256_add_epi64(e_biased, _mm256_set1_epi64x(0x4338000000000000))),
      _mm256_set1_pd(6755399441055744.0 + 1024.0));
  const __m256i m_bits = _mm256_sub_epi64(
      bits, _mm256_and_si256(relative, _mm256_set1_epi64x(std::int64_t(0xfff) << 52)));
  const __m256d m = _mm256_castsi256_pd(m_bits);
  const __m256d one = _mm256_set1_pd(1.0);
  const __m256d s = _mm256_div_pd(_mm256_sub_pd(m, one), _mm256_add_pd(m, one));
  const __m256d u = _mm256_mul_pd(s, s), u2 = _mm256_mul_pd(u, u);
  const __m256d p01 = _mm256_add_pd(_mm256_set1_pd(1.0000000000041793),
                                    _mm256_mul_pd(u, _mm256_set1_pd(0.33333332623755507)));
  const __m256d p23 = _mm256_add_pd(_mm256_set1_pd(0.20000192334836356),
                                    _mm256_mul_pd(u, _mm256_set1_pd(0.14267525577504317)));
  const __m256d p4 = _mm256_mul_pd(u2, _mm256_set1_pd(0.11808178694153203));
  const __m256d p = _mm256_add_pd(p01, _mm256_mul_pd(u2, _mm256_add_pd(p23, p4)));
  return _mm256_add_pd(_mm256_mul_pd(e, _mm256_set1_pd(M_LN2)),
                       _mm256_mul_pd(_mm256_mul_pd(_mm256_set1_pd(2.0), s), p));
}

/// Four J < 0 windows (repulsive() and window_of's shift in fast_engine_window.cpp); the
/// lanes off the common path are set in `special` and left to window_of.
SWARM_AVX2 void repulsive4(const Vec3* a, const Vec3* b, double inv_omega, double T2,
                           double phase_origin, double rounding, Window* out, int& special) {
  const Lanes A = load(a), B = load(b);
  const __m256d w = _mm256_set1_pd(inv_omega), half = _mm256_set1_pd(0.5);
  const Lanes bW = {_mm256_mul_pd(B.x, w), _mm256_mul_pd(B.y, w), _mm256_mul_pd(B.z, w)};
  const Lanes C = {_mm256_mul_pd(half, _mm256_add_pd(A.x, bW.x)),
                   _mm256_mul_pd(half, _mm256_add_pd(A.y, bW.y)),
                   _mm256_mul_pd(half, _mm256_add_pd(A.z, bW.z))};
  const Lanes D = {_mm256_mul_pd(half, _mm256_sub_pd(A.x, bW.x)),
                   _mm256_mul_pd(half, _mm256_sub_pd(A.y, bW.y)),
                   _mm256_mul_pd(half, _mm256_sub_pd(A.z, bW.z))};
  const __m256d two = _mm256_set1_pd(2.0), zero = _mm256_setzero_pd();
  const __m256d cc = dot(C, C), dd = dot(D, D);
  const __m256d beta = _mm256_sub_pd(_mm256_mul_pd(two, dot(C, D)), _mm256_set1_pd(T2));
  const __m256d disc = _mm256_sub_pd(_mm256_mul_pd(beta, beta),
                                     _mm256_mul_pd(_mm256_mul_pd(_mm256_set1_pd(4.0), cc), dd));
  // The common path: beta < 0, disc > 0, cc > 0 (each false for NaN, too).
  const __m256d common = _mm256_and_pd(
      _mm256_and_pd(_mm256_cmp_pd(beta, zero, _CMP_LT_OQ), _mm256_cmp_pd(disc, zero, _CMP_GT_OQ)),
      _mm256_cmp_pd(cc, zero, _CMP_GT_OQ));
  __m256i off =
      _mm256_castpd_si256(_mm256_xor_pd(common, _mm256_castsi256_pd(_mm256_set1_epi64x(-1))));
  const __m256d q =
      _mm256_add_pd(_mm256_sub_pd(zero, beta), _mm256_sqrt_pd(_mm256_max_pd(disc, zero)));
  const __m256d E_plus = _mm256_div_pd(q, _mm256_mul_pd(two, cc));
  const __m256d E_minus = _mm256_div_pd(_mm256_mul_pd(two, dd), q);
  const __m256d origin = _mm256_set1_pd(phase_origin), widen = _mm256_set1_pd(rounding);
  const __m256d error = _mm256_set1_pd(kLogError);
  const __m256d first =
      _mm256_add_pd(_mm256_add_pd(_mm256_add_pd(log4(E_minus, off), error), origin), widen);
  const __m256d second =
      _mm256_sub_pd(_mm256_add_pd(_mm256_sub_pd(log4(E_plus, off), error), origin), widen);
  alignas(32) double f[4], s[4];
  _mm256_store_pd(f, first);
  _mm256_store_pd(s, second);
  for (int j = 0; j < 4; ++j) out[j] = {f[j], s[j]};
  special = _mm256_movemask_pd(_mm256_castsi256_pd(off));
}

#endif  // SWARM_AVX2_BUILD

}  // namespace

bool windows_use_avx2() {
#ifdef SWARM_AVX2_BUILD
  return cpu_has_avx2();
#else
  return false;
#endif
}

void windows_of(const Vec3* a, const Vec3* b, std::size_t n, const Spring& spring, double T2,
                double phase_origin, Window* out) {
#ifdef SWARM_AVX2_BUILD
  if (spring.k < 0 && cpu_has_avx2()) {
    // window_of's widening for the rounding of the phase origin, computed as it does.
    const double rounding =
        4 * std::numeric_limits<double>::epsilon() * (std::abs(phase_origin) + 8);
    std::size_t j = 0;
    for (; j + 4 <= n; j += 4) {
      int special = 0;
      repulsive4(a + j, b + j, spring.inv_omega, T2, phase_origin, rounding, out + j, special);
      for (int l = 0; l < 4; ++l)
        if (special & (1 << l))
          out[j + l] = window_of(a[j + l], b[j + l], spring, T2, phase_origin);
    }
    if (j == n) return;
    // The last one to three go four at a time as well, padded with copies of the last (each
    // lane is computed on its own, so the padding changes nothing): a step's hits come in
    // chunks of a few dozen, and window_of one by one costs about four lanes.
    const std::size_t tail = n - j;
    Vec3 ta[4], tb[4];
    Window tw[4];
    for (std::size_t l = 0; l < 4; ++l) {
      ta[l] = a[j + std::min(l, tail - 1)];
      tb[l] = b[j + std::min(l, tail - 1)];
    }
    int special = 0;
    repulsive4(ta, tb, spring.inv_omega, T2, phase_origin, rounding, tw, special);
    for (std::size_t l = 0; l < tail; ++l)
      out[j + l] = special & (1 << l) ? window_of(ta[l], tb[l], spring, T2, phase_origin) : tw[l];
    return;
  }
#endif
  windows_one_by_one(a, b, n, spring, T2, phase_origin, out);
}

void off_centre_windows_of(const Vec3* a, const Vec3* b, std::size_t n, const Vec3& w,
                           const Spring& spring, double T2, double phase_origin, Window* out) {
#ifdef SWARM_AVX2_BUILD
  if (cpu_has_avx2()) {
    for (std::size_t j = 0; j < n; ++j)
      out[j] = off_centre_window_of_avx2(a[j], b[j], w, spring, T2, phase_origin);
    return;
  }
#endif
  for (std::size_t j = 0; j < n; ++j)
    out[j] = off_centre_window_of(a[j], b[j], w, spring, T2, phase_origin);
}

}  // namespace swarm::fast
