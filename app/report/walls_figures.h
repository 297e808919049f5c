#pragma once
// The figures of the Appendix B wall projects: the P-V loop of a moving wall, beside the
// adiabat a slow (reversible) move would follow.

#include <optional>

#include "report.h"

namespace swarmlab::report {

/// The P-V loop of a run whose container moves (preset.wall_moves); nothing otherwise.
std::optional<NamedFigure> pv_loop_figure(const RunRecord& r);

}  // namespace swarmlab::report
