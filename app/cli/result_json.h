#pragma once
// The RESULT.json and SAMPLES.csv that `swarmlab run` writes.

#include <string>

#include "swarm/preset.h"
#include "swarm/side_by_side.h"

namespace swarmlab {

/// summary, samples, stages, fits (when there are stages), comparisons and the final state.
std::string result_json(const swarm::Preset& preset, swarm::SideBySide& runs);
/// One row per sample: t,P,T,KE,PE,E,hits,R,work,heat,drag_loss,cm_height,size.
std::string samples_csv(const swarm::Run& run);

}  // namespace swarmlab
