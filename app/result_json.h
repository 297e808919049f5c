#pragma once
// The RESULT.json and SAMPLES.csv that `swarmlab run` writes.

#include <string>

#include "swarm/preset.h"

namespace swarmlab {

/// summary, samples, stages, fits (when there are stages) and the final state.
std::string result_json(const swarm::Preset& preset, swarm::ProtocolRun& run);
/// One row per sample: t,P,T,KE,PE,E,hits,R.
std::string samples_csv(const swarm::ProtocolRun& run);

}  // namespace swarmlab
