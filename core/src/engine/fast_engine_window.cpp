#include "engine/fast_engine_window.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "math/avx2.h"
#include "math/fast_math.h"
#include "math/portable_math.h"

namespace swarm::fast {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

Window attractive(const Vec3& a, const Vec3& b, double inv_omega, double T2) {
  const auto [P, Q, S, A] = swing_of(a, b, inv_omega);
  if (T2 <= P - A) return {0, 4};  // always at least sqrt(T2) from the origin
  if (T2 > P + A) return {0, -1};  // never
  // alpha = acos(cos_alpha); phi and alpha may each be off by kAtanError.
  const double cos_alpha = (T2 - P) / A;
  const double sin_alpha = std::sqrt(std::max(0.0, (1 - cos_alpha) * (1 + cos_alpha)));
  return {fast_atan2(S, Q), fast_atan2(sin_alpha, cos_alpha) + 2 * kAtanError};
}

Window repulsive(const Vec3& a, const Vec3& b, double inv_omega, double T2) {
  // h = C e^{Omega tau} + D e^{-Omega tau}; with E = e^{2 Omega tau},
  // E (|h|^2 - T2) = cc E^2 + beta E + dd, beta = 2 C.D - T2.
  const Vec3 bW = b * inv_omega;
  const Vec3 C = 0.5 * (a + bW), D = 0.5 * (a - bW);
  const double cc = C.squaredNorm(), dd = D.squaredNorm(), beta = 2 * C.dot(D) - T2;
  const double disc = beta * beta - 4 * cc * dd;
  if (beta >= 0 || disc <= 0) return {kInf, kInf};               // never negative for E > 0: always
  if (cc <= 0) return {fast_log(-dd / beta) + kLogError, kInf};  // only the decaying part
  // beta < 0, so neither root suffers cancellation.
  const double q = -beta + std::sqrt(disc);
  const double E_plus = q / (2 * cc), E_minus = 2 * dd / q;
  return {fast_log(E_minus) + kLogError, fast_log(E_plus) - kLogError};
}

Window free(const Vec3& a, const Vec3& b, double T2) {
  const double aa = a.squaredNorm(), ab = a.dot(b), bb = b.squaredNorm();
  if (bb <= 0) return aa >= T2 ? Window{kInf, kInf} : Window{-kInf, kInf};
  const double disc = ab * ab - bb * (aa - T2);
  if (disc <= 0) return {kInf, kInf};
  const double root = std::sqrt(disc);
  // One root without cancellation, the other from the product of the roots.
  if (ab <= 0) {
    const double tau_plus = (-ab + root) / bb;
    return {(aa - T2) / (bb * tau_plus), tau_plus};
  }
  const double tau_minus = (-ab - root) / bb;
  return {tau_minus, (aa - T2) / (bb * tau_minus)};
}

// A window that opens once a turn: an arc of half-width h about c, in phases of 2 theta.
Window once_a_turn(double c, double h) {
  if (h >= 2 * M_PI) return {0, 4};  // always
  return {c, kOnceATurn + h};
}

// Where |x(theta) + w|^2 - T2 = f(theta) = c0 + c1 cos(theta) + s1 sin(theta) + c2 cos(2
// theta) + s2 sin(2 theta) can be >= 0, from f's values at the kArcSamples points of a fixed
// grid round the turn, and at kArcRefine times finer ones where the arc found ends: between
// two points a distance d apart f is at most the straight line between its values plus bend
// s (d - s), s from the first point, where bend = max|f''| / 2 <= (|(c1, s1)| + 4 |(c2, s2)|)
// / 2 (linear interpolation's error), so at most their larger value plus bend d^2 / 4: where
// that is < 0 the interval is closed. The arc returned runs from the first open interval to
// the last, going round from the point where f is least: {lo, hi} in theta (on the fine
// grid), lo > hi when none is open.
struct ThetaArc {
  double lo, hi;
  int intervals;  // how many of the fine grid's: hi - lo = intervals 2 pi / kArcFine
};

constexpr int kArcSamples = 16;  // at most 32: bits of a mask
constexpr int kArcRefine = 8;
constexpr int kArcFine = kArcSamples * kArcRefine;  // a power of 2: indices wrap by a mask

// cos and sin of theta and 2 theta at the fine grid's angles theta = 2 pi j / kArcFine, and
// at the coarse grid's (every kArcRefine-th) in rows of their own, which vector instructions
// read straight through; the fine rows of 2 theta (fine_c2[j] = c[2 j mod kArcFine]) are for
// them, too.
struct SampledCircle {
  double c[kArcFine + 1], s[kArcFine + 1], fine_c2[kArcFine + 1], fine_s2[kArcFine + 1];
  double coarse_c[kArcSamples + 1], coarse_s[kArcSamples + 1], coarse_c2[kArcSamples + 1],
      coarse_s2[kArcSamples + 1];  // the turn's first point again at its end
  SampledCircle() {
    for (int j = 0; j < kArcFine; ++j) {
      // portable: the same table natively and in wasm (libm's last bits differ).
      c[j] = portable::cos(2 * M_PI * j / kArcFine);
      s[j] = portable::sin(2 * M_PI * j / kArcFine);
    }
    c[kArcFine] = c[0];
    s[kArcFine] = s[0];
    for (int j = 0; j <= kArcFine; ++j) {
      fine_c2[j] = c[(2 * j) % kArcFine];
      fine_s2[j] = s[(2 * j) % kArcFine];
    }
    for (int j = 0; j <= kArcSamples; ++j) {
      const int i = (j * kArcRefine) % kArcFine, i2 = (2 * i) % kArcFine;
      coarse_c[j] = c[i];
      coarse_s[j] = s[i];
      coarse_c2[j] = c[i2];
      coarse_s2[j] = s[i2];
    }
  }
};
const SampledCircle kCircle;

constexpr double kArcCoarseStep = 2 * M_PI / kArcSamples, kArcFineStep = kArcCoarseStep / kArcRefine;

// sampled_arc's work once the coarse grid is known: open (bit j: coarse interval j open) and
// origin (the first point where f is least) narrowed to the fine intervals that fine_open(k)
// finds open in coarse interval k (any k >= 0, taken modulo the turn).
// (Inlined into each caller: into sampled_arc_avx2, its AVX2 fine_open is inlined, too.)
template <class FineOpen>
__attribute__((always_inline)) inline ThetaArc arc_of_open(std::uint32_t open, int origin, const FineOpen& fine_open) {
  if (open == 0) return {1, 0, 0};
  const std::uint64_t twice = std::uint64_t(open) | std::uint64_t(open) << kArcSamples;
  const auto turned = std::uint32_t((twice >> origin) & ((std::uint64_t(1) << kArcSamples) - 1));
  int first = origin + __builtin_ctz(turned);
  int last = origin + 31 - __builtin_clz(turned);
  // From the first open fine interval of the coarse ones first .. last to the last (none
  // open: never).
  std::uint32_t bits = 0;
  for (; first <= last && !(bits = fine_open(first)); ++first) {
  }
  if (first > last) return {1, 0, 0};
  const int lo = first * kArcRefine + __builtin_ctz(bits);
  if (last > first) {
    for (; last > first && !(bits = fine_open(last)); --last) {
    }
    if (last == first) bits = fine_open(first);
  }
  const int hi = last * kArcRefine + 32 - __builtin_clz(bits);
  return {lo * kArcFineStep, hi * kArcFineStep, hi - lo};
}

ThetaArc sampled_arc(double c0, double c1, double s1, double c2, double s2, double bend,
                     double rounding) {
  const double base = c0 + rounding;
  double values[kArcSamples + 1];
  for (int j = 0; j <= kArcSamples; ++j)
    values[j] = base + c1 * kCircle.coarse_c[j] + s1 * kCircle.coarse_s[j] +
                c2 * kCircle.coarse_c2[j] + s2 * kCircle.coarse_s2[j];
  // Bit j: interval j, from point j to j + 1, is open.
  const double coarse_floor = -bend * kArcCoarseStep * kArcCoarseStep / 4;
  std::uint32_t open = 0;
  int origin = 0;  // the point where f is least
#pragma GCC unroll 16
  for (int j = 0; j < kArcSamples; ++j) {
    open |= std::uint32_t(std::max(values[j], values[j + 1]) >= coarse_floor) << j;
    origin = values[j] < values[origin] ? j : origin;
  }
  const auto f = [&](int i) {  // f at fine grid point i, any i >= 0
    i &= kArcFine - 1;
    const int i2 = (2 * i) & (kArcFine - 1);
    return base + c1 * kCircle.c[i] + s1 * kCircle.s[i] + c2 * kCircle.c[i2] +
           s2 * kCircle.s[i2];
  };
  const double fine_floor = -bend * kArcFineStep * kArcFineStep / 4;
  // Bit m: fine interval m of coarse interval k is open. Its points are evaluated together
  // (independent of each other, they overlap), not one by one until one is open.
  const auto fine_open = [&](int k) {
    double v[kArcRefine + 1];
#pragma GCC unroll 9
    for (int m = 0; m <= kArcRefine; ++m) v[m] = f(k * kArcRefine + m);
    std::uint32_t bits = 0;
#pragma GCC unroll 8
    for (int m = 0; m < kArcRefine; ++m)
      bits |= std::uint32_t(std::max(v[m], v[m + 1]) >= fine_floor) << m;
    return bits;
  };
  return arc_of_open(open, origin, fine_open);
}

#ifdef SWARM_AVX2_BUILD

// sampled_arc four grid points to a register. Each point's value is the scalar's sum, term by
// term in its order, of the same tables' entries (target("avx2") without "fma": nothing is
// fused), and _mm256_max_pd(y, x) is std::max(x, y), NaN and all: the same bits and the same
// arc.
struct ArcSum4 {
  __m256d base, c1, s1, c2, s2;
  __attribute__((target("avx2"))) __m256d at(const double* c, const double* s, const double* c2x,
                                             const double* s2x) const {
    return _mm256_add_pd(
        _mm256_add_pd(_mm256_add_pd(_mm256_add_pd(base, _mm256_mul_pd(c1, _mm256_loadu_pd(c))),
                                    _mm256_mul_pd(s1, _mm256_loadu_pd(s))),
                      _mm256_mul_pd(c2, _mm256_loadu_pd(c2x))),
        _mm256_mul_pd(s2, _mm256_loadu_pd(s2x)));
  }
  // Bits of the four intervals from points (v, shifted) that are open above `floor`.
  __attribute__((target("avx2"))) static std::uint32_t open4(__m256d v, __m256d shifted,
                                                            __m256d floor) {
    return std::uint32_t(_mm256_movemask_pd(
        _mm256_cmp_pd(_mm256_max_pd(shifted, v), floor, _CMP_GE_OQ)));
  }
  // sampled_arc's fine_open(k): the fine rows of 2 theta run on, and the tables hold the
  // turn's first point again at kArcFine, so the nine points are read straight through.
  __m256d fine_floor;
  __attribute__((target("avx2"))) __m256d at_fine(int j) const {
    return at(kCircle.c + j, kCircle.s + j, kCircle.fine_c2 + j, kCircle.fine_s2 + j);
  }
  __attribute__((target("avx2"))) std::uint32_t operator()(int k) const {
    const int i = (k & (kArcSamples - 1)) * kArcRefine;
    return open4(at_fine(i), at_fine(i + 1), fine_floor) |
           open4(at_fine(i + 4), at_fine(i + 5), fine_floor) << 4;
  }
};

__attribute__((target("avx2"))) ThetaArc sampled_arc_avx2(double c0, double c1, double s1,
                                                         double c2, double s2, double bend,
                                                         double rounding) {
  const ArcSum4 sum{_mm256_set1_pd(c0 + rounding), _mm256_set1_pd(c1), _mm256_set1_pd(s1),
                    _mm256_set1_pd(c2), _mm256_set1_pd(s2),
                    _mm256_set1_pd(-bend * kArcFineStep * kArcFineStep / 4)};
  __m256d v[4];
  for (int g = 0; g < 4; ++g)
    v[g] = sum.at(kCircle.coarse_c + 4 * g, kCircle.coarse_s + 4 * g,
                  kCircle.coarse_c2 + 4 * g, kCircle.coarse_s2 + 4 * g);
  // Points 1 to 4, 5 to 8, ..., 13 to 16 from the registers themselves (through memory, the
  // loads would wait on the stores), point kArcSamples being point 0 (the same tables'
  // entries).
  const __m256d coarse_floor = _mm256_set1_pd(-bend * kArcCoarseStep * kArcCoarseStep / 4);
  std::uint32_t open = 0;
  for (int g = 0; g < 4; ++g) {
    const __m256d next = _mm256_blend_pd(v[g], v[(g + 1) & 3], 1);  // its lane 0, v[g]'s others
    const __m256d shifted = _mm256_permute4x64_pd(next, 0x39);    // lanes 1, 2, 3, 0
    open |= ArcSum4::open4(v[g], shifted, coarse_floor) << (4 * g);
  }
  if (open == 0) return {1, 0, 0};
  // The first point where f is least: the first equal to the least value, as the scalar's
  // strict comparisons find it (-0 and +0 compare equal in both); with a NaN, its own loop.
  const __m256d least2 = _mm256_min_pd(_mm256_min_pd(v[0], v[1]), _mm256_min_pd(v[2], v[3]));
  int origin = 0;
  if (_mm256_movemask_pd(_mm256_or_pd(_mm256_cmp_pd(v[0], v[1], _CMP_UNORD_Q),
                                      _mm256_cmp_pd(v[2], v[3], _CMP_UNORD_Q)))) {
    alignas(32) double values[kArcSamples];
    for (int g = 0; g < 4; ++g) _mm256_store_pd(values + 4 * g, v[g]);
    for (int j = 0; j < kArcSamples; ++j) origin = values[j] < values[origin] ? j : origin;
  } else {
    __m256d least = _mm256_min_pd(least2, _mm256_permute2f128_pd(least2, least2, 1));
    least = _mm256_min_pd(least, _mm256_permute_pd(least, 5));
    std::uint32_t at_least = 0;
    for (int g = 0; g < 4; ++g)
      at_least |= std::uint32_t(_mm256_movemask_pd(_mm256_cmp_pd(v[g], least, _CMP_EQ_OQ)))
                  << (4 * g);
    origin = __builtin_ctz(at_least);
  }
  return arc_of_open(open, origin, sum);
}

#endif  // SWARM_AVX2_BUILD

using ArcFinder = ThetaArc (*)(double c0, double c1, double s1, double c2, double s2,
                               double bend, double rounding);

// x + w with x = a cos(theta) + B sin(theta), B = b / omega (fast_engine_window.h), in phases
// of 2 theta: never where S1 or S2 is; else the arc sampled_arc finds, or S1 where that is
// open for less time.
template <ArcFinder arc_of>
Window attractive_off_centre(const Vec3& a, const Vec3& b, const Vec3& w, double inv_omega,
                             double T2) {
  const double w2 = w.squaredNorm();
  const double inner = std::sqrt(T2) - std::sqrt(w2);
  const Vec3 B = b * inv_omega;
  const auto [P, Q, S, A] = swing_of(a, b, inv_omega);
  // S1 never: |x| <= sqrt(P + A) < inner (attractive's test).
  if (inner > 0 && inner * inner > P + A) return {0, -1};
  const double u = w.dot(a), v = w.dot(B), rho = std::sqrt(u * u + v * v);
  // S2 never: |x + w|^2 <= P + A + 2 rho + |w|^2 < T2, by far more than its rounding.
  const double sum = T2 + P + A + w2;
  if (T2 - P - A - w2 - 1e-12 * sum > 2 * rho) return {0, -1};
  // f = |x + w|^2 - T2, raised by far more than its rounding; |f''| <= 2 rho + 4 A.
  const ThetaArc arc = arc_of(P + w2 - T2, 2 * u, 2 * v, Q, S, rho + 2 * A, 1e-12 * sum);
  if (arc.lo > arc.hi) return {0, -1};
  // S1 is open 4 alpha of every 4 pi, the arc 2 (hi - lo) = 4 x: S1 is open for less time
  // where alpha < x, cos(alpha) = (inner^2 - P) / A > cos(x) (x = (arc.hi - arc.lo) / 2 <=
  // pi, cos(x) = +-sqrt((1 + cos 2x) / 2) from the grid's table). Either window holds every
  // crossing, so the rounding of the choice does not matter. S1 is always when inner <= 0 or
  // inner^2 <= P - A.
  const double lo = 2 * arc.lo, hi = 2 * arc.hi;
  const double cos_2x = kCircle.c[arc.intervals & (kArcFine - 1)];
  const double cos_x = std::copysign(std::sqrt(0.5 * (1 + cos_2x)), kArcFine / 2 - arc.intervals);
  if (inner > 0 && A > 0 && (inner * inner - P) / A > cos_x) {
    const Window s1 = attractive(a, b, inv_omega, inner * inner);
    if (s1.second >= 0 && hi - lo >= 4 * s1.second) return s1;
  }
  return once_a_turn(0.5 * (lo + hi), 0.5 * (hi - lo) + 1e-12);
}

// h_z = A cos(theta - phi) <= L: |theta - phi - pi| <= alpha, cos alpha = -L / A.
Window attractive_floor(double a_z, double b_z, double inv_omega, double L) {
  const double B = b_z * inv_omega;
  const double A = std::sqrt(a_z * a_z + B * B);
  if (L >= A) return {0, 4};    // always at or below L
  if (L < -A) return {0, -1};  // never
  const double cos_alpha = -L / A;
  const double sin_alpha = std::sqrt(std::max(0.0, (1 - cos_alpha) * (1 + cos_alpha)));
  return {fast_atan2(B, a_z) + M_PI, fast_atan2(sin_alpha, cos_alpha) + 2 * kAtanError};
}

// h_z = C u + D / u, u = exp(Omega tau): h_z <= L where q(u) = C u^2 - L u + D <= 0.
Window repulsive_floor(double a_z, double b_z, double inv_omega, double L) {
  const double bW = b_z * inv_omega;
  const double C = 0.5 * (a_z + bW), D = 0.5 * (a_z - bW);
  const auto log_of = [](double u) { return u > 0 ? fast_log(u) : -kInf; };
  if (C == 0) {
    if (L > 0) return {-kInf, log_of(D / L) - kLogError};  // u >= D / L
    if (L < 0) return {D / L > 0 ? log_of(D / L) + kLogError : -kInf, kInf};  // u <= D / L
    return D <= 0 ? Window{kInf, kInf} : Window{-kInf, kInf};
  }
  const double disc = L * L - 4 * C * D;
  if (disc < 0) return C > 0 ? Window{-kInf, kInf} : Window{kInf, kInf};
  // The roots without cancellation: one from the quadratic formula, the other from their
  // product D / C.
  const double q = 0.5 * (L + std::copysign(std::sqrt(disc), L));
  const double r1 = q / C, r2 = q != 0 ? D / q : 0.0;
  const double lo = std::min(r1, r2), hi = std::max(r1, r2);
  if (C > 0) return {-kInf, hi <= 0 ? kInf : log_of(lo) - kLogError};  // lo <= u <= hi
  return {lo > 0 ? log_of(lo) + kLogError : -kInf, log_of(hi) - kLogError};  // u <= lo, u >= hi
}

// h_z = a_z + b_z tau <= L.
Window free_floor(double a_z, double b_z, double L) {
  if (b_z == 0) return a_z <= L ? Window{kInf, kInf} : Window{-kInf, kInf};
  const double tau = (L - a_z) / b_z;
  return b_z > 0 ? Window{tau, kInf} : Window{-kInf, tau};
}

}  // namespace

Window floor_window_of(double a_z, double b_free_z, const Spring& spring, double L_now,
                       double phase_origin, double growth) {
  const bool damped = spring.eta != 0;
  if (damped && L_now >= 0) return always_window(spring.k);
  const double b_z = damped ? b_free_z + spring.eta * a_z : b_free_z;
  const double L = damped ? L_now * std::sqrt(growth) : L_now;
  const double rounding = 4 * std::numeric_limits<double>::epsilon() * (std::abs(phase_origin) + 8);
  if (spring.k > 0) {
    const Window w = attractive_floor(a_z, b_z, spring.inv_omega, L);
    return {w.first + phase_origin,
            w.second < 0 || w.second >= M_PI ? w.second : w.second + rounding};
  }
  const Window w =
      spring.k < 0 ? repulsive_floor(a_z, b_z, spring.inv_omega, L) : free_floor(a_z, b_z, L);
  return {w.first + phase_origin + rounding, w.second + phase_origin - rounding};
}

Window window_of(const Vec3& a, const Vec3& b_free, const Spring& spring, double T2_now,
                 double phase_origin, double growth) {
  const bool damped = spring.eta != 0;
  const Vec3 b = damped ? Vec3(b_free + spring.eta * a) : b_free;
  const double T2 = damped ? T2_now * growth : T2_now;
  // Each phase moves by the origin's; its rounding widens the window.
  const double rounding = 4 * std::numeric_limits<double>::epsilon() * (std::abs(phase_origin) + 8);
  if (spring.k > 0) {
    const Window w = attractive(a, b, spring.inv_omega, T2);
    return {w.first + phase_origin,
            w.second < 0 || w.second >= M_PI ? w.second : w.second + rounding};
  }
  const Window w = spring.k < 0 ? repulsive(a, b, spring.inv_omega, T2) : free(a, b, T2);
  return {w.first + phase_origin + rounding, w.second + phase_origin - rounding};
}

namespace {

template <ArcFinder arc_of>
Window off_centre_window(const Vec3& a, const Vec3& b, const Vec3& w, const Spring& spring,
                         double T2, double phase_origin) {
  if (spring.k == 0) return window_of(a + w, b, spring, T2, phase_origin);  // exact
  if (spring.k < 0) {
    const double inner = std::sqrt(T2) - w.norm();
    return inner > 0 ? window_of(a, b, spring, inner * inner, phase_origin)
                     : always_window(spring.k);
  }
  const Window win = attractive_off_centre<arc_of>(a, b, w, spring.inv_omega, T2);
  if (win.second < 0 || (win.second >= M_PI && win.second < kOnceATurn)) return win;
  const double rounding = 4 * std::numeric_limits<double>::epsilon() * (std::abs(phase_origin) + 8);
  return {win.first + phase_origin, win.second + rounding};
}

}  // namespace

Window off_centre_window_of(const Vec3& a, const Vec3& b, const Vec3& w, const Spring& spring,
                            double T2, double phase_origin) {
  return off_centre_window<sampled_arc>(a, b, w, spring, T2, phase_origin);
}

Window off_centre_window_of_avx2(const Vec3& a, const Vec3& b, const Vec3& w,
                                 const Spring& spring, double T2, double phase_origin) {
#ifdef SWARM_AVX2_BUILD
  return off_centre_window<sampled_arc_avx2>(a, b, w, spring, T2, phase_origin);
#else
  return off_centre_window<sampled_arc>(a, b, w, spring, T2, phase_origin);
#endif
}

Window always_window(double k) {
  if (k > 0) return {0, 4};
  return {kInf, kInf};
}

Window never_window(double k) {
  if (k > 0) return {0, -1};
  return {-kInf, kInf};
}

}  // namespace swarm::fast
