#pragma once
/// Confidence intervals over independent runs: the mean's Student-t interval, and the BCa
/// bootstrap (Efron, J. Am. Stat. Assoc. 82, 171 (1987)) for a statistic that is not a mean
/// (a fitted exponent), resampling whole runs.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace swarm {

/// The standard normal's distribution function, and its inverse for p in (0, 1).
double normal_cdf(double x);
double normal_quantile(double p);
/// Student's t distribution with `dof` > 0 degrees of freedom: its distribution function and
/// its p-quantile (p in (0, 1)); 12.706 for p = 0.975 and one degree of freedom.
double student_t_cdf(double t, double dof);
double student_t_quantile(double p, double dof);

/// What n independent values say about their mean.
struct MeanInterval {
  std::size_t n = 0;
  double mean = 0;
  double sd = 0;  ///< sample standard deviation (n - 1); 0 for one value
  double se = 0;  ///< sd / sqrt(n)
  /// The 95 % Student-t interval, mean -/+ t(0.975, n - 1) se; none for fewer than 2 values.
  std::optional<double> lo, hi;
};
MeanInterval mean_interval(const std::vector<double>& values, double confidence = 0.95);

/// How many independent runs make the interval's half-width at most `half_width`, given the
/// spread sd seen so far (the t quantile grows as runs fall, so it is solved for n): 0 when
/// sd is 0, -1 when half_width is not > 0.
long runs_for_half_width(double sd, double half_width, double confidence = 0.95);

/// A statistic of a resample: `runs` holds run indices, some repeated, some missing.
using RunStatistic = std::function<double(const std::vector<std::size_t>& runs)>;

struct BootstrapInterval {
  double estimate = 0;  ///< the statistic over all runs
  double lo = 0, hi = 0;
  double bias = 0;          ///< z0, the median bias correction
  double acceleration = 0;  ///< a, from the jackknife
  int resamples = 0;
};

/// The BCa interval of a statistic of n >= 3 runs from `resamples` resamples drawn with a
/// counter-based generator keyed on `seed` and the resample's number (the same interval on
/// every machine). None when fewer than 3 runs, or when the statistic is not finite on every
/// resample and jackknife sample.
std::optional<BootstrapInterval> bca_interval(std::size_t runs, const RunStatistic& statistic,
                                              double confidence = 0.95, int resamples = 2000,
                                              std::uint64_t seed = 1);

}  // namespace swarm
