#pragma once
/// Whether a fitted power law describes its points, judged from the residuals (paper
/// Appendix C). Apart from fit.h so that the run and everything it includes do not depend on it.

#include <cstddef>

#include "swarm/measure/fit.h"

namespace swarm {

/// Whether a power law describes the points, from its residuals (paper Appendix C: a straight
/// line on log-log axes can look convincing while the residuals, in the order of the points,
/// wave or trend, which no power law explains).
struct PowerLawAdequacy {
  /// Durbin-Watson statistic sum (e_i - e_{i-1})^2 / sum e_i^2 of the residuals in point order:
  /// about 2 for independent scatter, near 0 when neighbours share their sign (a wave, a
  /// trend, a curve); 2 when every residual is zero.
  double durbin_watson = 2;
  bool scattered = false;   ///< R^2 < kMinRSquared: the points hardly follow any line
  bool systematic = false;  ///< at least kMinPointsForPattern points and DW < kMaxSystematicDW
  bool poor() const { return scattered || systematic; }

  static constexpr double kMinRSquared = 0.9;
  static constexpr double kMaxSystematicDW = 1.0;  ///< about the 1% point for 10-20 points
  static constexpr std::size_t kMinPointsForPattern = 6;
};

/// Judges a valid fit; an invalid one is neither scattered nor systematic.
PowerLawAdequacy judge_power_law(const PowerLawFit& fit);

}  // namespace swarm
