#include "swarm/measure/power_law_adequacy.h"

namespace swarm {

PowerLawAdequacy judge_power_law(const PowerLawFit& fit) {
  PowerLawAdequacy a;
  if (!fit.valid) return a;
  const std::vector<double>& e = fit.residuals;
  double ss = 0, ss_diff = 0;
  for (std::size_t i = 0; i < e.size(); ++i) {
    ss += e[i] * e[i];
    if (i > 0) ss_diff += (e[i] - e[i - 1]) * (e[i] - e[i - 1]);
  }
  // Residuals at rounding level carry no pattern worth a warning.
  if (ss > 1e-24 * double(e.size())) a.durbin_watson = ss_diff / ss;
  a.scattered = fit.r_squared < PowerLawAdequacy::kMinRSquared;
  a.systematic = e.size() >= PowerLawAdequacy::kMinPointsForPattern &&
                 a.durbin_watson < PowerLawAdequacy::kMaxSystematicDW;
  return a;
}

}  // namespace swarm
