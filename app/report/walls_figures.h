#pragma once
// The figures of the Appendix B wall projects: the P-V loop of a moving wall, beside the
// adiabat a slow (reversible) move would follow, and the final speeds against the Maxwellian.

#include <optional>

#include "report/figure.h"
#include "report/run_record.h"

namespace swarmlab::report {

/// The P-V loop of a run whose container moves (preset.wall_moves); nothing otherwise.
std::optional<NamedFigure> pv_loop_figure(const RunRecord& r);
/// The histogram of the final speeds against the Maxwell distribution at the gas's kinetic
/// temperature, with the KS distance (a run with a hot wall or hard spheres); else nothing.
std::optional<NamedFigure> speed_histogram_figure(const RunRecord& r);

}  // namespace swarmlab::report
