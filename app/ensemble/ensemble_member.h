#pragma once
// One member of an ensemble run to its record: the same code whether `swarmlab ensemble` runs
// it on a worker thread or a runner calls `swarmlab run --record` from the manifest, so run k
// is the same bits either way.

#include <string>

#include "ensemble/run_record.h"
#include "swarm/preset/preset.h"

namespace swarmlab::ensemble {

/// Runs `preset` (already seeded, swarm::with_seed) with `threads` engine threads (the results
/// do not depend on it) and writes its record whole to record_path, also when the run stopped
/// on a number that left the range of a double (the record says why). Returns "" or a message
/// about the file.
std::string run_member(const swarm::Preset& preset, const RunIdentity& id,
                       const std::string& record_path, int threads);

}  // namespace swarmlab::ensemble
