#pragma once
/// Least-squares power laws y = a x^b on log-log axes, with residuals (paper Appendix C).

#include <vector>

namespace swarm {

struct PowerLawFit {
  double slope = 0;         ///< the exponent b
  double slope_stderr = 0;  ///< standard error of b
  double intercept = 0;     ///< ln a
  double r_squared = 0;
  std::vector<double> residuals;  ///< ln y - (intercept + slope ln x), one per point used
  std::vector<int> used;          ///< indices of the points used (x > 0 and y > 0)
  bool valid = false;             ///< at least three usable points
};

/// Fits ln y = intercept + slope ln x over the points with x > 0 and y > 0.
PowerLawFit fit_power_law(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace swarm
