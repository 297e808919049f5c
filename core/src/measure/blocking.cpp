#include "swarm/measure/blocking.h"

#include <cmath>

namespace swarm {
namespace {

/// The 99 % quantile of the chi-square distribution with k degrees of freedom (Wilson and
/// Hilferty's cube-root approximation: 6.59 for k = 1 against 6.63, closer as k grows).
double chi_square_99(int k) {
  const double z = 2.3263478740408408;  // the normal's 99 % quantile
  const double a = 2.0 / (9.0 * k);
  const double c = 1 - a + z * std::sqrt(a);
  return k * c * c * c;
}

}  // namespace

std::optional<BlockingError> blocking_error(const std::vector<double>& values) {
  const std::size_t n = values.size();
  if (n < 4) return std::nullopt;
  BlockingError out;
  for (double v : values) out.mean += v;
  out.mean /= double(n);
  double all_squares = 0;
  for (double v : values) all_squares += (v - out.mean) * (v - out.mean);
  out.naive_se = std::sqrt(all_squares / double(n - 1) / double(n));

  // Level i holds m_i = floor(m_(i-1) / 2) values, neighbours averaged in pairs (a value
  // left over at the end of a level is dropped): its variance s[i] (over m_i, about its own
  // mean) and the chi-square term of its lag-1 covariance.
  std::vector<double> x = values;
  std::vector<double> s, term;
  std::vector<std::size_t> size;
  while (x.size() >= 2) {
    const std::size_t m = x.size();
    double mu = 0;
    for (double v : x) mu += v;
    mu /= double(m);
    double var = 0, cov = 0;
    for (std::size_t t = 0; t < m; ++t) var += (x[t] - mu) * (x[t] - mu);
    for (std::size_t t = 0; t + 1 < m; ++t) cov += (x[t] - mu) * (x[t + 1] - mu);
    var /= double(m);
    cov /= double(m);
    s.push_back(var);
    size.push_back(m);
    // Uncorrelated pairs: sqrt(m) cov / var is about standard normal, its square chi-square(1).
    term.push_back(var > 0 ? double(m) * (cov / var) * (cov / var) : 0.0);
    for (std::size_t t = 0; t < m / 2; ++t) x[t] = 0.5 * (x[2 * t] + x[2 * t + 1]);
    x.resize(m / 2);
  }
  const int d = int(s.size());
  out.used = long(n);
  // M_j = sum of the terms of levels j..d-1, chi-square(d - j) when none is correlated.
  std::vector<double> tail(std::size_t(d) + 1, 0.0);
  for (int i = d - 1; i >= 0; --i) tail[std::size_t(i)] = tail[std::size_t(i) + 1] + term[std::size_t(i)];
  out.level = d - 1;
  out.plateau = false;
  for (int j = 0; j < d; ++j)
    if (tail[std::size_t(j)] < chi_square_99(d - j)) {
      out.level = j;
      out.plateau = true;
      break;
    }
  const double m = double(size[std::size_t(out.level)]);
  out.se = std::sqrt(s[std::size_t(out.level)] / (m - 1));
  out.effective_count = out.se > 0 ? double(n) * (out.naive_se / out.se) * (out.naive_se / out.se)
                                   : double(n);
  return out;
}

std::optional<BlockingError> blocking_error_of_ratio(const std::vector<double>& numerators,
                                                     const std::vector<double>& weights) {
  const std::size_t n = std::min(numerators.size(), weights.size());
  double top = 0, bottom = 0;
  for (std::size_t i = 0; i < n; ++i) top += numerators[i], bottom += weights[i];
  if (!(bottom != 0)) return std::nullopt;
  const double ratio = top / bottom, mean_weight = bottom / double(n);
  std::vector<double> linear(n);
  for (std::size_t i = 0; i < n; ++i)
    linear[i] = (numerators[i] - ratio * weights[i]) / mean_weight;
  std::optional<BlockingError> e = blocking_error(linear);
  if (e) e->mean = ratio;  // the linearised series averages to 0; its error is the ratio's
  return e;
}

}  // namespace swarm
