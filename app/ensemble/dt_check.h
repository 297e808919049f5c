#pragma once
// The time step's systematic beside the statistical interval: `swarmlab ensemble --dt-check`
// runs the same seeds again at dt / 2 into DIR/dt-half/, and the merge pairs each run with its
// twin. The mean paired shift (run at dt / 2 minus run at dt) with its Student-t 95 % interval
// is what halving dt moves each quantity by; for a scheme of first order in dt the bias at dt
// itself is about minus twice that. Pairing cancels most of the between-seed spread, so the
// shift is measured far more finely than the quantity's own interval.

#include <nlohmann/json.hpp>
#include <string>

#include "ensemble/ensemble_plan.h"

namespace swarmlab::ensemble {

/// Where the runs at dt / 2 live, inside the ensemble's folder.
inline constexpr const char* kDtHalfFolder = "dt-half";

/// The preset at dt / 2 over the same time: samples at the same times (a given sample_every
/// doubles); everything else the same.
swarm::Preset with_half_dt(const swarm::Preset& p);

/// The dt check of the ensemble in `dir` (one point, its plan `plan`, its report's
/// `quantities`) against the runs in dir/dt-half: per quantity `shift`, `relative` (over the
/// mean of the paired runs at dt), `ci95` (the shift's), `pairs`, `half_width` (the
/// quantity's own 95 % half-width), `bias_at_dt` (-2 shift, first order) and
/// `statistics_wider` (whether that half-width exceeds |bias_at_dt|), and a line per quantity
/// for the terminal table. `error` when dir/dt-half holds
/// something else than the same seeds at dt / 2 (another plan, preset or version); null json
/// and no error when there is no dir/dt-half.
struct DtCheck {
  nlohmann::json report;  ///< null when there is no check
  std::string table;
  std::string error;
};
DtCheck dt_check(const std::string& dir, const EnsemblePlan& plan, const nlohmann::json& quantities);

}  // namespace swarmlab::ensemble
