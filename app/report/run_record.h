#pragma once
// Everything a report draws from one run, whether the run just finished in this process or
// was saved earlier as RESULT.json (so that two saved runs can be overlaid without re-running).

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "report/provenance.h"
#include "swarm/measure/speed_distribution.h"
#include "swarm/preset/preset.h"
#include "swarm/run/side_by_side.h"

namespace swarmlab::report {

struct ComparisonTrack {
  std::string method;
  double energy_drift = 0;
  std::vector<swarm::ComparisonSample> samples;
};

struct RunRecord {
  swarm::Preset preset;
  swarm::RunSummary summary;
  std::vector<swarm::Sample> samples;
  std::vector<swarm::Stage> stages;
  std::vector<ComparisonTrack> comparisons;  ///< measured against preset.method
  /// With a hot wall or hard spheres: the final speeds against the Maxwellian.
  std::optional<swarm::SpeedCheck> final_speeds;
  /// What made the run, when its RESULT.json says (files written before it did not).
  std::optional<Provenance> made_by{};
};

RunRecord record_of(const swarm::Preset& preset, swarm::SideBySide& runs);

struct RecordRead {
  std::optional<RunRecord> record;
  std::string error;  ///< names the file and what is wrong with it
};

/// The most a saved run (RESULT.json) or an ensemble's report may hold: they carry every
/// sample, the final particles or a value per run, hundreds of MB for a long run of many
/// particles, still far below this.
inline constexpr std::size_t kResultFileLimit = std::size_t(2) << 30;

/// Reads a RESULT.json written by `swarmlab run --out`.
RecordRead read_result_file(const std::string& path);

}  // namespace swarmlab::report
