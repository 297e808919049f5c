#include "swarm/measure/confidence.h"

#include <algorithm>
#include <cmath>

#include "math/splitmix.h"

namespace swarm {
namespace {

/// The continued fraction of the regularised incomplete beta function (modified Lentz).
double beta_fraction(double a, double b, double x) {
  const double tiny = 1e-300;
  double c = 1, d = 1 - (a + b) * x / (a + 1);
  if (std::abs(d) < tiny) d = tiny;
  d = 1 / d;
  double h = d;
  for (int m = 1; m <= 300; ++m) {
    const double m2 = 2.0 * m;
    double aa = m * (b - m) * x / ((a + m2 - 1) * (a + m2));
    d = 1 + aa * d;
    c = 1 + aa / c;
    if (std::abs(d) < tiny) d = tiny;
    if (std::abs(c) < tiny) c = tiny;
    d = 1 / d;
    h *= d * c;
    aa = -(a + m) * (a + b + m) * x / ((a + m2) * (a + m2 + 1));
    d = 1 + aa * d;
    c = 1 + aa / c;
    if (std::abs(d) < tiny) d = tiny;
    if (std::abs(c) < tiny) c = tiny;
    d = 1 / d;
    const double step = d * c;
    h *= step;
    if (std::abs(step - 1) < 1e-15) break;
  }
  return h;
}

/// I_x(a, b), the regularised incomplete beta function.
double incomplete_beta(double a, double b, double x) {
  if (x <= 0) return 0;
  if (x >= 1) return 1;
  const double front = std::exp(std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) +
                                a * std::log(x) + b * std::log1p(-x));
  if (x < (a + 1) / (a + b + 2)) return front * beta_fraction(a, b, x) / a;
  return 1 - front * beta_fraction(b, a, 1 - x) / b;
}

/// The x in [lo, hi] at which an increasing f reaches p, by bisection to the last bit.
template <class F>
double invert(F f, double p, double lo, double hi) {
  for (int i = 0; i < 200 && hi - lo > 0; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid == lo || mid == hi) break;
    (f(mid) < p ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}


}  // namespace

double normal_cdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

double normal_quantile(double p) { return invert(normal_cdf, p, -40.0, 40.0); }

double student_t_cdf(double t, double dof) {
  const double tail = 0.5 * incomplete_beta(0.5 * dof, 0.5, dof / (dof + t * t));
  return t >= 0 ? 1 - tail : tail;
}

double student_t_quantile(double p, double dof) {
  // |t| < 1e8 holds every quantile up to p = 1 - 1e-9 for one degree of freedom and beyond.
  return invert([dof](double t) { return student_t_cdf(t, dof); }, p, -1e8, 1e8);
}

MeanInterval mean_interval(const std::vector<double>& values, double confidence) {
  MeanInterval out;
  out.n = values.size();
  if (out.n == 0) return out;
  for (double v : values) out.mean += v;
  out.mean /= double(out.n);
  if (out.n < 2) return out;
  double squares = 0;
  for (double v : values) squares += (v - out.mean) * (v - out.mean);
  out.sd = std::sqrt(squares / double(out.n - 1));
  out.se = out.sd / std::sqrt(double(out.n));
  const double t = student_t_quantile(0.5 + 0.5 * confidence, double(out.n - 1));
  out.lo = out.mean - t * out.se;
  out.hi = out.mean + t * out.se;
  return out;
}

long runs_for_half_width(double sd, double half_width, double confidence) {
  if (!(sd > 0)) return 0;
  if (!(half_width > 0)) return -1;
  const double p = 0.5 + 0.5 * confidence;
  // t(n - 1) sd / sqrt(n) falls as n grows: double n until it is enough, then bisect.
  auto enough = [&](long m) {
    return student_t_quantile(p, double(m - 1)) * sd / std::sqrt(double(m)) <= half_width;
  };
  long hi = 2;
  while (!enough(hi)) {
    if (hi > (1L << 40)) return hi;
    hi *= 2;
  }
  long lo = std::max(2L, hi / 2);
  if (enough(lo)) return lo;
  while (hi - lo > 1) {
    const long mid = lo + (hi - lo) / 2;
    (enough(mid) ? hi : lo) = mid;
  }
  return hi;
}

std::optional<BootstrapInterval> bca_interval(std::size_t runs, const RunStatistic& statistic,
                                              double confidence, int resamples,
                                              std::uint64_t seed) {
  if (runs < 3 || resamples < 10) return std::nullopt;
  std::vector<std::size_t> all(runs);
  for (std::size_t i = 0; i < runs; ++i) all[i] = i;
  BootstrapInterval out;
  out.estimate = statistic(all);
  out.resamples = resamples;
  if (!std::isfinite(out.estimate)) return std::nullopt;

  std::vector<double> replicas(static_cast<std::size_t>(resamples));
  std::vector<std::size_t> pick(runs);
  const std::uint64_t key = splitmix64(seed);
  for (int b = 0; b < resamples; ++b) {
    for (std::size_t i = 0; i < runs; ++i) {
      const std::uint64_t r = splitmix64(key ^ splitmix64((std::uint64_t(b) << 32) + i));
      pick[i] = std::size_t(r % runs);  // bias below 2^-40 for any runs this merge sees
    }
    replicas[std::size_t(b)] = statistic(pick);
    if (!std::isfinite(replicas[std::size_t(b)])) return std::nullopt;
  }
  // z0: how far the resamples' median sits from the estimate (ties count half).
  double below = 0;
  for (double r : replicas) below += r < out.estimate ? 1.0 : r == out.estimate ? 0.5 : 0.0;
  const double fraction = std::clamp(below / resamples, 0.5 / resamples, 1 - 0.5 / resamples);
  out.bias = normal_quantile(fraction);

  // a: the skewness of the jackknife (each run left out in turn).
  std::vector<double> jack(runs);
  std::vector<std::size_t> without(runs - 1);
  for (std::size_t k = 0; k < runs; ++k) {
    for (std::size_t i = 0, j = 0; i < runs; ++i)
      if (i != k) without[j++] = i;
    jack[k] = statistic(without);
    if (!std::isfinite(jack[k])) return std::nullopt;
  }
  double jack_mean = 0;
  for (double j : jack) jack_mean += j;
  jack_mean /= double(runs);
  double s2 = 0, s3 = 0;
  for (double j : jack) {
    const double d = jack_mean - j;
    s2 += d * d;
    s3 += d * d * d;
  }
  out.acceleration = s2 > 0 ? s3 / (6 * std::pow(s2, 1.5)) : 0;

  std::sort(replicas.begin(), replicas.end());
  auto quantile_at = [&](double z_alpha) {
    const double z = out.bias + z_alpha;
    const double level = normal_cdf(out.bias + z / (1 - out.acceleration * z));
    // The resamples' empirical quantile, interpolated between neighbours.
    const double pos = std::clamp(level * (resamples - 1), 0.0, double(resamples - 1));
    const std::size_t i = std::size_t(pos);
    const double f = pos - double(i);
    return i + 1 < replicas.size() ? (1 - f) * replicas[i] + f * replicas[i + 1] : replicas[i];
  };
  const double z = normal_quantile(0.5 + 0.5 * confidence);
  out.lo = quantile_at(-z);
  out.hi = quantile_at(z);
  return out;
}

}  // namespace swarm
