#pragma once
// Under each power-law fit of the expansion tab: its residuals plotted against x, R^2, the
// Durbin-Watson statistic, and a warning when the residuals say the power law does not
// describe the stages (swarm::judge_power_law, the paper's Appendix C).

#include <vector>

#include "swarm/measure/power_law_adequacy.h"

namespace swarmlab {

struct AppState;

/// x: the stages' x values the fit was made over (fit.used indexes them).
void draw_fit_quality(const char* id, const std::vector<double>& x, const swarm::PowerLawFit& fit,
                      bool log_x, float height, AppState& state);

}  // namespace swarmlab
