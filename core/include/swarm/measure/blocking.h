#pragma once
/// The standard error of the mean of a correlated series, by blocking (Flyvbjerg and
/// Petersen, J. Chem. Phys. 91, 461 (1989)) with the level chosen automatically (Jonsson,
/// Phys. Rev. E 98, 043304 (2018)).
///
/// Neighbouring values of a time series (the wall's P in consecutive intervals, a particle's
/// energy) are correlated, so sd / sqrt(n) is the wrong error of their mean: too small when
/// they stay alike for a while, too large when they alternate. Averaging neighbours in pairs,
/// again and again, gives series whose values are further and further apart in time; once
/// pairs are no longer correlated, each level's sd / sqrt(n) is the true error. The level
/// chosen is the first from which on no level shows a lag-1 correlation larger than chance
/// allows (a chi-square test at 99 %).

#include <optional>
#include <vector>

namespace swarm {

struct BlockingError {
  double mean = 0;  ///< of all the values
  double se = 0;    ///< standard error of the mean, at the chosen level
  /// sd / sqrt(n) of the values as if they were independent: se / naive_se is how much
  /// the correlations widen (> 1) or narrow (< 1) the error.
  double naive_se = 0;
  /// The values that count as independent, n (naive_se / se)^2.
  double effective_count = 0;
  int level = 0;      ///< times the series was halved to reach the chosen level
  long used = 0;      ///< values used: all of them
  bool plateau = true;  ///< false: no level passed the test (the series is too short)
};

/// The blocking error of the mean of `values` (at least 4 of them; none otherwise). A level
/// of odd length drops its last value when it is halved.
std::optional<BlockingError> blocking_error(const std::vector<double>& values);

/// The same for a ratio of sums, sum(numerators) / sum(weights) (a wall temperature: the hits'
/// kinetic energy over the hits, interval by interval): blocked on the linearised series
/// (numerator_i - ratio * weight_i) / mean(weight). None when the weights sum to zero.
std::optional<BlockingError> blocking_error_of_ratio(const std::vector<double>& numerators,
                                                     const std::vector<double>& weights);

}  // namespace swarm
