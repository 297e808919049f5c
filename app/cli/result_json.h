#pragma once
// The RESULT.json that `swarmlab run` writes (its --csv: report/run_csv.h).

#include <string>

#include "report/provenance.h"
#include "swarm/preset/preset.h"
#include "swarm/run/side_by_side.h"

namespace swarmlab {

/// provenance (what made it: made_by), summary, samples, stages, fits (when there are
/// stages), comparisons and the final state.
std::string result_json(const swarm::Preset& preset, swarm::SideBySide& runs,
                        const report::Provenance& made_by);

}  // namespace swarmlab
