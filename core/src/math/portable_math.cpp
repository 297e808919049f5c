// fdlibm's elementary functions as FreeBSD msun and musl carry them, in C++ (see
// portable_math.h for why the core has its own). The algorithms, constants and operation order
// are fdlibm's; only the C library's bit-access macros became the helpers below.
//
// ====================================================
// Copyright (C) 1993, 2004 by Sun Microsystems, Inc. All rights reserved.
//
// Developed at SunSoft, a Sun Microsystems, Inc. business.
// Permission to use, copy, modify, and distribute this
// software is freely granted, provided that this notice
// is preserved.
// ====================================================
// cosh and sinh follow musl's versions (MIT licence, Copyright 2005-2020 Rich Felker et al.).
//
// [SECTION] bit access
// [SECTION] sin, cos: kernels, argument reduction (Cody-Waite, Payne-Hanek), the functions
// [SECTION] exp, expm1, cosh, sinh
// [SECTION] log
// [SECTION] atan, atan2

#include "math/portable_math.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace swarm::portable {
namespace {

// [SECTION] bit access ---------------------------------------------------------------------

std::uint64_t bits_of(double x) {
  std::uint64_t u;
  std::memcpy(&u, &x, sizeof u);
  return u;
}

double from_bits(std::uint64_t u) {
  double x;
  std::memcpy(&x, &u, sizeof x);
  return x;
}

std::uint32_t high_word(double x) { return std::uint32_t(bits_of(x) >> 32); }
std::uint32_t low_word(double x) { return std::uint32_t(bits_of(x)); }

/// x 2^n, exact (as scalbn is on every IEEE platform) for the normal results used here.
double scale2(double x, int n) { return std::ldexp(x, n); }

// [SECTION] sin, cos -----------------------------------------------------------------------

// k_sin.c: sin(x + y) for |x| <= pi/4, y the tail of x; iy == 0 when y is 0.
constexpr double S1 = -1.66666666666666324348e-01, S2 = 8.33333333332248946124e-03,
                 S3 = -1.98412698298579493134e-04, S4 = 2.75573137070700676789e-06,
                 S5 = -2.50507602534068634195e-08, S6 = 1.58969099521155010221e-10;

double kernel_sin(double x, double y, int iy) {
  const double z = x * x;
  const double w = z * z;
  const double r = S2 + z * (S3 + z * S4) + z * w * (S5 + z * S6);
  const double v = z * x;
  if (iy == 0) return x + v * (S1 + z * r);
  return x - ((z * (0.5 * y - v * r) - y) - v * S1);
}

// k_cos.c: cos(x + y) for |x| <= pi/4.
constexpr double C1 = 4.16666666666666019037e-02, C2 = -1.38888888888741095749e-03,
                 C3 = 2.48015872894767294178e-05, C4 = -2.75573143513906633035e-07,
                 C5 = 2.08757232129817482790e-09, C6 = -1.13596475577881948265e-11;

double kernel_cos(double x, double y) {
  const double z = x * x;
  double w = z * z;
  const double r = z * (C1 + z * (C2 + z * C3)) + w * w * (C4 + z * (C5 + z * C6));
  const double hz = 0.5 * z;
  w = 1.0 - hz;
  return w + (((1.0 - w) - hz) + (z * r - x * y));
}

// k_rem_pio2.c (Payne-Hanek): 2/pi to 1584 bits in 24-bit chunks, enough for any double.
constexpr std::int32_t kTwoOverPi[] = {
    0xA2F983, 0x6E4E44, 0x1529FC, 0x2757D1, 0xF534DD, 0xC0DB62, 0x95993C, 0x439041, 0xFE5163,
    0xABDEBB, 0xC561B7, 0x246E3A, 0x424DD2, 0xE00649, 0x2EEA09, 0xD1921C, 0xFE1DEB, 0x1CB129,
    0xA73EE8, 0x8235F5, 0x2EBB44, 0x84E99C, 0x7026B4, 0x5F7E41, 0x3991D6, 0x398353, 0x39F49C,
    0x845F8B, 0xBDF928, 0x3B1FF8, 0x97FFDE, 0x05980F, 0xEF2F11, 0x8B5A0A, 0x6D1F6D, 0x367ECF,
    0x27CB09, 0xB74F46, 0x3F669E, 0x5FEA2D, 0x7527BA, 0xC7EBE5, 0xF17B3D, 0x0739F7, 0x8A5292,
    0xEA6BFB, 0x5FB11F, 0x8D5D08, 0x560330, 0x46FC7B, 0x6BABF0, 0xCFBC20, 0x9AF436, 0x1DA9E3,
    0x91615E, 0xE61B08, 0x659985, 0x5F14A0, 0x68408D, 0xFFD880, 0x4D7327, 0x310606, 0x1556CA,
    0x73A8C9, 0x60E27B, 0xC08C6B,
};

// pi/2 in 24-bit pieces.
constexpr double kPiOver2Pieces[] = {
    1.57079625129699707031e+00, 7.54978941586159635335e-08, 5.39030252995776476554e-15,
    3.28200341580791294123e-22, 1.27065575308067607349e-29, 1.22933308981111328932e-36,
    2.73370053816464559624e-44, 2.16741683877804819444e-51,
};

/// x (nx 24-bit chunks of |x| 2^-e0) mod pi/2 into y[0] + y[1]; returns the quadrant mod 8.
/// fdlibm's __kernel_rem_pio2 for double precision (prec = 1).
int rem_pio2_large(const double* x, double* y, int e0, int nx) {
  constexpr int jk = 4;  // init_jk[1]: terms of 2/pi beyond the integer part
  constexpr int jp = jk;
  std::int32_t iq[20];
  double f[20], fq[20], q[20];

  const int jx = nx - 1;
  int jv = (e0 - 3) / 24;
  if (jv < 0) jv = 0;
  int q0 = e0 - 24 * (jv + 1);

  for (int i = 0, j = jv - jx; i <= jx + jk; i++, j++) f[i] = j < 0 ? 0.0 : double(kTwoOverPi[j]);
  for (int i = 0; i <= jk; i++) {
    double fw = 0.0;
    for (int j = 0; j <= jx; j++) fw += x[j] * f[jx + i - j];
    q[i] = fw;
  }

  int jz = jk;
  int n, ih;
  double z;
  for (;;) {
    // Distill q[] into iq[] in reverse.
    int i = 0;
    z = q[jz];
    for (int j = jz; j > 0; i++, j--) {
      const double fw = double(std::int32_t(0x1p-24 * z));
      iq[i] = std::int32_t(z - 0x1p24 * fw);
      z = q[j - 1] + fw;
    }
    z = scale2(z, q0);
    z -= 8.0 * std::floor(z * 0.125);  // trim off integers >= 8
    n = std::int32_t(z);
    z -= double(n);
    ih = 0;
    if (q0 > 0) {  // iq[jz-1] is needed to determine n
      const std::int32_t top = iq[jz - 1] >> (24 - q0);
      n += top;
      iq[jz - 1] -= top << (24 - q0);
      ih = iq[jz - 1] >> (23 - q0);
    } else if (q0 == 0) {
      ih = iq[jz - 1] >> 23;
    } else if (z >= 0.5) {
      ih = 2;
    }
    if (ih > 0) {  // q > 0.5: take 1 - q
      n += 1;
      int carry = 0;
      for (int k = 0; k < jz; k++) {
        const std::int32_t j = iq[k];
        if (carry == 0) {
          if (j != 0) {
            carry = 1;
            iq[k] = 0x1000000 - j;
          }
        } else {
          iq[k] = 0xffffff - j;
        }
      }
      if (q0 == 1) iq[jz - 1] &= 0x7fffff;
      if (q0 == 2) iq[jz - 1] &= 0x3fffff;
      if (ih == 2) {
        z = 1.0 - z;
        if (carry != 0) z -= scale2(1.0, q0);
      }
    }
    if (z != 0.0) break;
    std::int32_t any = 0;
    for (int k = jz - 1; k >= jk; k--) any |= iq[k];
    if (any != 0) break;
    // Cancellation: take more terms of 2/pi and compute again.
    int more = 1;
    while (iq[jk - more] == 0) more++;
    for (int k = jz + 1; k <= jz + more; k++) {
      f[jx + k] = double(kTwoOverPi[jv + k]);
      double fw = 0.0;
      for (int j = 0; j <= jx; j++) fw += x[j] * f[jx + k - j];
      q[k] = fw;
    }
    jz += more;
  }

  // Chop off zero terms, or break z into 24-bit chunks.
  if (z == 0.0) {
    jz -= 1;
    q0 -= 24;
    while (iq[jz] == 0) {
      jz--;
      q0 -= 24;
    }
  } else {
    z = scale2(z, -q0);
    if (z >= 0x1p24) {
      const double fw = double(std::int32_t(0x1p-24 * z));
      iq[jz] = std::int32_t(z - 0x1p24 * fw);
      jz += 1;
      q0 += 24;
      iq[jz] = std::int32_t(fw);
    } else {
      iq[jz] = std::int32_t(z);
    }
  }

  double fw = scale2(1.0, q0);
  for (int i = jz; i >= 0; i--) {
    q[i] = fw * double(iq[i]);
    fw *= 0x1p-24;
  }
  for (int i = jz; i >= 0; i--) {
    fw = 0.0;
    for (int k = 0; k <= jp && k <= jz - i; k++) fw += kPiOver2Pieces[k] * q[i + k];
    fq[jz - i] = fw;
  }
  fw = 0.0;
  for (int i = jz; i >= 0; i--) fw += fq[i];
  y[0] = ih == 0 ? fw : -fw;
  fw = fq[0] - fw;
  for (int i = 1; i <= jz; i++) fw += fq[i];
  y[1] = ih == 0 ? fw : -fw;
  return n & 7;
}

// e_rem_pio2.c: x = n pi/2 + y[0] + y[1] with |y[0] + y[1]| <= pi/4 (roughly); returns n.
// The caller handles |x| <= pi/4.
constexpr double kToInt = 1.5 / std::numeric_limits<double>::epsilon();
constexpr double kPiOver4 = 0x1.921fb54442d18p-1;
constexpr double kInvPiOver2 = 6.36619772367581382433e-01;
constexpr double kPio2_1 = 1.57079632673412561417e+00;   // first 33 bits of pi/2
constexpr double kPio2_1t = 6.07710050650619224932e-11;  // pi/2 - kPio2_1
constexpr double kPio2_2 = 6.07710050630396597660e-11;   // second 33 bits
constexpr double kPio2_2t = 2.02226624879595063154e-21;
constexpr double kPio2_3 = 2.02226624871116645580e-21;  // third 33 bits
constexpr double kPio2_3t = 8.47842766036889956997e-32;

int rem_pio2_medium(double x, std::uint32_t ix, double* y) {
  // Cody-Waite: n = rint(x / (pi/2)) and x - n pi/2 in up to three rounds.
  double fn = x * kInvPiOver2 + kToInt - kToInt;
  int n = std::int32_t(fn);
  double r = x - fn * kPio2_1;
  double w = fn * kPio2_1t;  // first round, good to 85 bits
  if (r - w < -kPiOver4) {   // only under directed rounding
    n--;
    fn--;
    r = x - fn * kPio2_1;
    w = fn * kPio2_1t;
  } else if (r - w > kPiOver4) {
    n++;
    fn++;
    r = x - fn * kPio2_1;
    w = fn * kPio2_1t;
  }
  y[0] = r - w;
  const int ex = int(ix >> 20);
  int ey = int(bits_of(y[0]) >> 52 & 0x7ff);
  if (ex - ey > 16) {  // second round, good to 118 bits
    double t = r;
    w = fn * kPio2_2;
    r = t - w;
    w = fn * kPio2_2t - ((t - r) - w);
    y[0] = r - w;
    ey = int(bits_of(y[0]) >> 52 & 0x7ff);
    if (ex - ey > 49) {  // third round, good to 151 bits, covers all cases
      t = r;
      w = fn * kPio2_3;
      r = t - w;
      w = fn * kPio2_3t - ((t - r) - w);
      y[0] = r - w;
    }
  }
  y[1] = (r - y[0]) - w;
  return n;
}

int rem_pio2(double x, double* y) {
  const std::uint64_t u = bits_of(x);
  const bool negative = u >> 63;
  const std::uint32_t ix = std::uint32_t(u >> 32) & 0x7fffffff;
  // Near the first few multiples of pi/2 one subtraction of a two-part pi/2 suffices, except
  // right at a multiple, where the cancellation needs the medium case.
  const auto near = [&](int k, double* out) {
    const double s = negative ? 1.0 : -1.0;
    const double z = x + s * k * kPio2_1;
    out[0] = z + s * k * kPio2_1t;
    out[1] = (z - out[0]) + s * k * kPio2_1t;
    return negative ? -k : k;
  };
  if (ix <= 0x400f6a7a) {                                             // |x| ~<= 5pi/4
    if ((ix & 0xfffff) == 0x921fb) return rem_pio2_medium(x, ix, y);  // ~ pi/2 or pi
    return near(ix <= 0x4002d97c ? 1 : 2, y);                         // 3pi/4 splits them
  }
  if (ix <= 0x401c463b) {  // |x| ~<= 9pi/4
    if (ix <= 0x4015fdbc) {
      if (ix == 0x4012d97c) return rem_pio2_medium(x, ix, y);  // ~ 3pi/2
      return near(3, y);
    }
    if (ix == 0x401921fb) return rem_pio2_medium(x, ix, y);  // ~ 2pi
    return near(4, y);
  }
  if (ix < 0x413921fb) return rem_pio2_medium(x, ix, y);  // |x| ~< 2^20 pi/2
  if (ix >= 0x7ff00000) {                                 // inf or NaN
    y[0] = y[1] = x - x;
    return 0;
  }
  // Large: |x| = z 2^(e0) with z in [2^23, 2^24), split into three 24-bit chunks.
  double z = from_bits((u & (std::uint64_t(-1) >> 12)) | (std::uint64_t(0x3ff + 23) << 52));
  double tx[3], ty[2];
  int i = 0;
  for (; i < 2; i++) {
    tx[i] = double(std::int32_t(z));
    z = (z - tx[i]) * 0x1p24;
  }
  tx[i] = z;
  while (tx[i] == 0.0) i--;  // skip zero terms; the first is non-zero
  const int n = rem_pio2_large(tx, ty, int(ix >> 20) - (0x3ff + 23), i + 1);
  if (negative) {
    y[0] = -ty[0];
    y[1] = -ty[1];
    return -n;
  }
  y[0] = ty[0];
  y[1] = ty[1];
  return n;
}

// [SECTION] exp, expm1, cosh, sinh ---------------------------------------------------------

constexpr double kLn2Hi = 6.93147180369123816490e-01;  // n kLn2Hi is exact for |n| < 2000
constexpr double kLn2Lo = 1.90821492927058770002e-10;
constexpr double kInvLn2 = 1.44269504088896338700e+00;
constexpr double kExpOverflow = 7.09782712893383973096e+02;

// The rest of exp(x) / 2 for x beyond log(DBL_MAX) (musl's __expo2): exp(x - k ln2) 2^(k-1)
// with k odd and chosen so that k ln2 has a small relative error.
double exp_over_2_large(double x, double sign) {
  constexpr int k = 2043;
  constexpr double k_ln2 = 0x1.62066151add8bp+10;
  const double scale = from_bits(std::uint64_t((0x3ff + k / 2) << 20) << 32);
  return exp(x - k_ln2) * (sign * scale) * scale;
}

}  // namespace

double sin(double x) {
  const std::uint32_t ix = high_word(x) & 0x7fffffff;
  if (ix <= 0x3fe921fb) {           // |x| ~<= pi/4
    if (ix < 0x3e500000) return x;  // |x| < 2^-26
    return kernel_sin(x, 0.0, 0);
  }
  if (ix >= 0x7ff00000) return x - x;  // NaN
  double y[2];
  switch (unsigned(rem_pio2(x, y)) & 3) {
    case 0:
      return kernel_sin(y[0], y[1], 1);
    case 1:
      return kernel_cos(y[0], y[1]);
    case 2:
      return -kernel_sin(y[0], y[1], 1);
    default:
      return -kernel_cos(y[0], y[1]);
  }
}

double cos(double x) {
  const std::uint32_t ix = high_word(x) & 0x7fffffff;
  if (ix <= 0x3fe921fb) {             // |x| ~<= pi/4
    if (ix < 0x3e46a09e) return 1.0;  // |x| < 2^-27 sqrt 2
    return kernel_cos(x, 0.0);
  }
  if (ix >= 0x7ff00000) return x - x;  // NaN
  double y[2];
  switch (unsigned(rem_pio2(x, y)) & 3) {
    case 0:
      return kernel_cos(y[0], y[1]);
    case 1:
      return -kernel_sin(y[0], y[1], 1);
    case 2:
      return -kernel_cos(y[0], y[1]);
    default:
      return kernel_sin(y[0], y[1], 1);
  }
}

void sincos(double x, double* sin_x, double* cos_x) {
  const std::uint32_t ix = high_word(x) & 0x7fffffff;
  if (ix <= 0x3fe921fb) {
    if (ix < 0x3e46a09e) {
      *sin_x = x;
      *cos_x = 1.0;
      return;
    }
    *sin_x = kernel_sin(x, 0.0, 0);
    *cos_x = kernel_cos(x, 0.0);
    return;
  }
  if (ix >= 0x7ff00000) {
    *sin_x = *cos_x = x - x;
    return;
  }
  double y[2];
  const unsigned n = unsigned(rem_pio2(x, y));
  const double s = kernel_sin(y[0], y[1], 1);
  const double c = kernel_cos(y[0], y[1]);
  switch (n & 3) {
    case 0:
      *sin_x = s;
      *cos_x = c;
      break;
    case 1:
      *sin_x = c;
      *cos_x = -s;
      break;
    case 2:
      *sin_x = -s;
      *cos_x = -c;
      break;
    default:
      *sin_x = -c;
      *cos_x = s;
      break;
  }
}

// e_exp.c: x = k ln2 + r with |r| <= ln2 / 2, exp(r) from a rational function of r whose
// polynomial part (P1..P5) is a Remez fit good to 2^-59.
double exp(double x) {
  constexpr double P1 = 1.66666666666666019037e-01, P2 = -2.77777777770155933842e-03,
                   P3 = 6.61375632143793436117e-05, P4 = -1.65339022054652515390e-06,
                   P5 = 4.13813679705723846039e-08;
  const std::uint32_t hx_signed = high_word(x);
  const int sign = int(hx_signed >> 31);
  const std::uint32_t hx = hx_signed & 0x7fffffff;

  if (hx >= 0x4086232b) {  // |x| >= 708.39...
    if (std::isnan(x)) return x;
    if (x > kExpOverflow) return x * 0x1p1023;  // overflow to inf
    if (x < -745.13321910194110842) return 0;
  }

  double hi, lo;
  int k;
  if (hx > 0x3fd62e42) {     // |x| > ln2 / 2
    if (hx >= 0x3ff0a2b2) {  // |x| >= 1.5 ln2
      k = int(kInvLn2 * x + (sign ? -0.5 : 0.5));
    } else {
      k = 1 - sign - sign;
    }
    hi = x - k * kLn2Hi;  // exact
    lo = k * kLn2Lo;
    x = hi - lo;
  } else if (hx > 0x3e300000) {  // |x| > 2^-28
    k = 0;
    hi = x;
    lo = 0;
  } else {
    return 1 + x;
  }

  const double xx = x * x;
  const double c = x - xx * (P1 + xx * (P2 + xx * (P3 + xx * (P4 + xx * P5))));
  const double y = 1 + (x * c / (2 - c) - lo + hi);
  if (k == 0) return y;
  return scale2(y, k);
}

// s_expm1.c: the same reduction as exp, with a rational approximation of expm1(r) that keeps
// the small result's relative accuracy.
double expm1(double x) {
  constexpr double Q1 = -3.33333333333331316428e-02, Q2 = 1.58730158725481460165e-03,
                   Q3 = -7.93650757867487942473e-05, Q4 = 4.00821782732936239552e-06,
                   Q5 = -2.01099218183624371326e-07;
  const std::uint64_t u = bits_of(x);
  const std::uint32_t hx = std::uint32_t(u >> 32) & 0x7fffffff;
  const int sign = int(u >> 63);

  if (hx >= 0x4043687A) {  // |x| >= 56 ln2
    if (std::isnan(x)) return x;
    if (sign) return -1;
    if (x > kExpOverflow) return x * 0x1p1023;
  }

  double c;
  int k;
  if (hx > 0x3fd62e42) {  // |x| > ln2 / 2
    double hi, lo;
    if (hx < 0x3FF0A2B2) {  // and |x| < 1.5 ln2
      if (!sign) {
        hi = x - kLn2Hi;
        lo = kLn2Lo;
        k = 1;
      } else {
        hi = x + kLn2Hi;
        lo = -kLn2Lo;
        k = -1;
      }
    } else {
      k = int(kInvLn2 * x + (sign ? -0.5 : 0.5));
      const double t = k;
      hi = x - t * kLn2Hi;  // exact
      lo = t * kLn2Lo;
    }
    x = hi - lo;
    c = (hi - x) - lo;
  } else if (hx < 0x3c900000) {  // |x| < 2^-54
    return x;
  } else {
    k = 0;
    c = 0;
  }

  const double hfx = 0.5 * x;
  const double hxs = x * hfx;
  const double r1 = 1.0 + hxs * (Q1 + hxs * (Q2 + hxs * (Q3 + hxs * (Q4 + hxs * Q5))));
  const double t = 3.0 - r1 * hfx;
  double e = hxs * ((r1 - t) / (6.0 - x * t));
  if (k == 0) return x - (x * e - hxs);
  e = x * (e - c) - c;
  e -= hxs;
  // exp(x) ~ 2^k (x_reduced - e + 1)
  if (k == -1) return 0.5 * (x - e) - 0.5;
  if (k == 1) {
    if (x < -0.25) return -2.0 * (e - (x + 0.5));
    return 1.0 + 2.0 * (x - e);
  }
  const double two_k = from_bits(std::uint64_t(0x3ff + k) << 52);
  if (k < 0 || k > 56) {  // exp(x) - 1 is exp(x) to within rounding
    double y = x - e + 1.0;
    y = k == 1024 ? y * 2.0 * 0x1p1023 : y * two_k;
    return y - 1.0;
  }
  const double two_minus_k = from_bits(std::uint64_t(0x3ff - k) << 52);
  if (k < 20) return (x - e + (1 - two_minus_k)) * two_k;
  return (x - (e + two_minus_k) + 1) * two_k;
}

// musl's cosh: (exp(x) + 1/exp(x)) / 2, through expm1 near 0 where that would cancel.
double cosh(double x) {
  x = std::fabs(x);
  const std::uint32_t w = high_word(x);
  if (w < 0x3fe62e42) {                         // |x| < ln2
    if (w < 0x3ff00000 - (26 << 20)) return 1;  // |x| < 2^-26
    const double t = expm1(x);
    return 1 + t * t / (2 * (1 + t));
  }
  if (w < 0x40862e42) {  // |x| < log(DBL_MAX)
    const double t = exp(x);
    return 0.5 * (t + 1 / t);
  }
  return exp_over_2_large(x, 1.0);  // or NaN
}

// musl's sinh: (exp(x) - 1/exp(x)) / 2 written through t = expm1(|x|).
double sinh(double x) {
  const double h = std::signbit(x) ? -0.5 : 0.5;
  const double absx = std::fabs(x);
  const std::uint32_t w = high_word(absx);
  if (w < 0x40862e42) {  // |x| < log(DBL_MAX)
    const double t = expm1(absx);
    if (w < 0x3ff00000) {                         // |x| < 1
      if (w < 0x3ff00000 - (26 << 20)) return x;  // |x| < 2^-26
      return h * (2 * t - t * t / (t + 1));
    }
    return h * (t + t / (t + 1));
  }
  return exp_over_2_large(absx, 2 * h);  // or NaN
}

// [SECTION] log ----------------------------------------------------------------------------

// e_log.c: x = 2^k (1 + f) with sqrt(2)/2 < 1 + f < sqrt 2, log(1 + f) through
// s = f / (2 + f) and a Remez polynomial (Lg1..Lg7) good to 2^-58.45.
double log(double x) {
  constexpr double Lg1 = 6.666666666666735130e-01, Lg2 = 3.999999999940941908e-01,
                   Lg3 = 2.857142874366239149e-01, Lg4 = 2.222219843214978396e-01,
                   Lg5 = 1.818357216161805012e-01, Lg6 = 1.531383769920937332e-01,
                   Lg7 = 1.479819860511658591e-01;
  std::uint64_t u = bits_of(x);
  std::uint32_t hx = std::uint32_t(u >> 32);
  int k = 0;
  if (hx < 0x00100000 || hx >> 31) {
    if (u << 1 == 0) return -std::numeric_limits<double>::infinity();  // log(+-0)
    if (hx >> 31) return std::numeric_limits<double>::quiet_NaN();     // log(negative)
    k -= 54;                                                           // subnormal: scale up
    x *= 0x1p54;
    u = bits_of(x);
    hx = std::uint32_t(u >> 32);
  } else if (hx >= 0x7ff00000) {
    return x;  // inf or NaN
  } else if (hx == 0x3ff00000 && u << 32 == 0) {
    return 0;
  }

  // Reduce x into [sqrt(2)/2, sqrt 2].
  hx += 0x3ff00000 - 0x3fe6a09e;
  k += int(hx >> 20) - 0x3ff;
  hx = (hx & 0x000fffff) + 0x3fe6a09e;
  x = from_bits(std::uint64_t(hx) << 32 | (u & 0xffffffff));

  const double f = x - 1.0;
  const double hfsq = 0.5 * f * f;
  const double s = f / (2.0 + f);
  const double z = s * s;
  const double w = z * z;
  const double t1 = w * (Lg2 + w * (Lg4 + w * Lg6));
  const double t2 = z * (Lg1 + w * (Lg3 + w * (Lg5 + w * Lg7)));
  const double R = t2 + t1;
  const double dk = k;
  return s * (hfsq + R) + dk * kLn2Lo - hfsq + f + dk * kLn2Hi;
}

// [SECTION] atan, atan2 --------------------------------------------------------------------

// s_atan.c: |x| reduced to near 0, 1/2, 1, 3/2 or infinity, then an odd polynomial.
double atan(double x) {
  constexpr double atanhi[] = {4.63647609000806093515e-01, 7.85398163397448278999e-01,
                               9.82793723247329054082e-01, 1.57079632679489655800e+00};
  constexpr double atanlo[] = {2.26987774529616870924e-17, 3.06161699786838301793e-17,
                               1.39033110312309984516e-17, 6.12323399573676603587e-17};
  constexpr double aT[] = {
      3.33333333333329318027e-01,  -1.99999999998764832476e-01, 1.42857142725034663711e-01,
      -1.11111104054623557880e-01, 9.09088713343650656196e-02,  -7.69187620504482999495e-02,
      6.66107313738753120669e-02,  -5.83357013379057348645e-02, 4.97687799461593236017e-02,
      -3.65315727442169155270e-02, 1.62858201153657823623e-02};
  const std::uint32_t hx = high_word(x);
  const bool negative = hx >> 31;
  const std::uint32_t ix = hx & 0x7fffffff;
  if (ix >= 0x44100000) {  // |x| >= 2^66
    if (std::isnan(x)) return x;
    return negative ? -atanhi[3] : atanhi[3];
  }
  int id;
  if (ix < 0x3fdc0000) {            // |x| < 0.4375
    if (ix < 0x3e400000) return x;  // |x| < 2^-27
    id = -1;
  } else {
    x = std::fabs(x);
    if (ix < 0x3ff30000) {    // |x| < 1.1875
      if (ix < 0x3fe60000) {  // 7/16 <= |x| < 11/16
        id = 0;
        x = (2.0 * x - 1.0) / (2.0 + x);
      } else {  // 11/16 <= |x| < 19/16
        id = 1;
        x = (x - 1.0) / (x + 1.0);
      }
    } else if (ix < 0x40038000) {  // |x| < 2.4375
      id = 2;
      x = (x - 1.5) / (1.0 + 1.5 * x);
    } else {  // 2.4375 <= |x| < 2^66
      id = 3;
      x = -1.0 / x;
    }
  }
  const double z = x * x;
  const double w = z * z;
  // The sum of aT[i] z^(i+1) split into odd and even polynomials.
  const double s1 =
      z * (aT[0] + w * (aT[2] + w * (aT[4] + w * (aT[6] + w * (aT[8] + w * aT[10])))));
  const double s2 = w * (aT[1] + w * (aT[3] + w * (aT[5] + w * (aT[7] + w * aT[9]))));
  if (id < 0) return x - x * (s1 + s2);
  const double r = atanhi[id] - (x * (s1 + s2) - atanlo[id] - x);
  return negative ? -r : r;
}

// e_atan2.c: atan(|y/x|) moved into the right quadrant, with the special cases of IEEE 754.
double atan2(double y, double x) {
  constexpr double pi = 3.1415926535897931160E+00;
  constexpr double pi_lo = 1.2246467991473531772E-16;
  if (std::isnan(x) || std::isnan(y)) return x + y;
  std::uint32_t ix = high_word(x), iy = high_word(y);
  const std::uint32_t lx = low_word(x), ly = low_word(y);
  if (((ix - 0x3ff00000) | lx) == 0) return atan(y);        // x = 1
  const int m = int((iy >> 31) & 1) | int((ix >> 30) & 2);  // 2 sign(x) + sign(y)
  ix &= 0x7fffffff;
  iy &= 0x7fffffff;

  if ((iy | ly) == 0) {  // y = 0
    switch (m) {
      case 0:
      case 1:
        return y;
      case 2:
        return pi;
      default:
        return -pi;
    }
  }
  if ((ix | lx) == 0) return m & 1 ? -pi / 2 : pi / 2;  // x = 0
  if (ix == 0x7ff00000) {                               // x = inf
    if (iy == 0x7ff00000) {
      switch (m) {
        case 0:
          return pi / 4;
        case 1:
          return -pi / 4;
        case 2:
          return 3 * pi / 4;
        default:
          return -3 * pi / 4;
      }
    }
    switch (m) {
      case 0:
        return 0.0;
      case 1:
        return -0.0;
      case 2:
        return pi;
      default:
        return -pi;
    }
  }
  if (ix + (64 << 20) < iy || iy == 0x7ff00000) return m & 1 ? -pi / 2 : pi / 2;  // |y/x| > 2^64

  double z;
  if ((m & 2) && iy + (64 << 20) < ix) {  // |y/x| < 2^-64, x < 0
    z = 0;
  } else {
    z = atan(std::fabs(y / x));
  }
  switch (m) {
    case 0:
      return z;
    case 1:
      return -z;
    case 2:
      return pi - (z - pi_lo);
    default:
      return (z - pi_lo) - pi;
  }
}

}  // namespace swarm::portable
