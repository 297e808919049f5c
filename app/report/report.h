#pragma once
// Which figures a run produces. A run draws what it has: energies over time for every run;
// wall pressure and temperature for a container; the stage relations and their log-log fits
// (paper Figs. 2, 3 and Appendix C) for an expansion; energy and position error for methods
// run side by side; and the closed analytic orbits for a small isolated attractive system
// (Fig. 1). Several saved runs can be overlaid stage by stage (Fig. 5).

#include <string>
#include <vector>

#include "report/figure.h"
#include "report/run_record.h"

namespace swarmlab::report {

/// The most points a drawn series keeps (plotting/decimate.h), so that SVG files stay small.
inline constexpr std::size_t kMaxPointsPerSeries = 2000;

std::vector<NamedFigure> run_figures(const RunRecord& run);

/// T-V, P-V and P-T of several expansion runs in one set of axes, the first solid and the
/// others dashed. Runs without stages are left out; fewer than one with stages gives nothing.
std::vector<NamedFigure> overlay_figures(const std::vector<RunRecord>& runs);

}  // namespace swarmlab::report
