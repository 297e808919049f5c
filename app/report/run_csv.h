#pragma once
// A run's samples and stages as CSV: the one writer behind `swarmlab run --csv` and the app's
// Export CSV, so that a file from either has the same columns. Every field quoted
// (report/csv_field.h): "t","P","T",... then one row of numbers per sample. No provenance
// comment lines, unlike the figures' CSV (provenance.h): the header stays the first line, as
// a spreadsheet and the tests (`head -1`) read it; `run --out` carries the run's provenance.

#include <string>
#include <vector>

#include "swarm/run/run.h"

namespace swarmlab::report {

/// The samples' column names, in order: t,P,T,KE,PE,E,hits,R, then the energy books
/// (work, heat, drag_loss since t = 0), the CM's height, the swarm's rms size and T_kinetic,
/// (2/3) KE / N in the CM frame beside the wall's T. T_kinetic came last so that a sheet
/// written for the earlier columns reads them where they were.
inline constexpr const char* kSamplesCsvHeader =
    "t,P,T,KE,PE,E,hits,R,work,heat,drag_loss,cm_height,size,T_kinetic";
/// The stages' column names, in order: the values of RESULT.json's "stages", T_kinetic last
/// (as in the samples).
inline constexpr const char* kStagesCsvHeader = "R,V,P,T,E,hits,T_kinetic";

/// One row per sample, full precision (17 significant digits) so the file re-reads exactly.
std::string samples_csv(const std::vector<swarm::Sample>& samples);
/// One row per finished expansion stage, full precision.
std::string stages_csv(const std::vector<swarm::Stage>& stages);

}  // namespace swarmlab::report
