#pragma once
// The merge of an ensemble's runs: which are missing, failed or corrupted, and per quantity the
// values over the runs with their mean, spread and 95 % interval (Student-t for means, BCa
// bootstrap over whole runs for the fitted exponents), the within-run errors against the
// between-run spread, and bands on P(t), T(t) and the stages. Runs are read one at a time.

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "ensemble/ensemble_plan.h"
#include "ensemble/run_record.h"

namespace swarmlab::ensemble {

struct RunScan {
  std::vector<long> done;     ///< complete records of this plan, finished or failed
  std::vector<long> missing;  ///< no file yet
  std::vector<std::pair<long, std::string>> corrupted;  ///< index, what is wrong
  std::vector<std::pair<long, std::string>> failed;     ///< index, why the run stopped
  /// Files that belong to another plan, preset, version or run: a message naming each, and
  /// the merge refuses to mix them in. "" when none.
  std::string mixed;
};

/// Reads DIR/runs/ against the plan; `each` sees every complete, matching record in index order.
RunScan scan_runs(const std::string& dir, const EnsemblePlan& plan,
                  const std::function<void(const RunRecord&)>& each = {});

struct MergeReport {
  std::string error;   ///< "" or one message (no plan, mixed runs, nothing finished)
  std::string json;    ///< REPORT.json
  std::string csv;     ///< one row per run: index, seed, every quantity
  std::string table;   ///< the terminal summary
};

/// relative_half_width: the report says how many runs make each mean's 95 % interval this
/// narrow relative to the mean (0.01: +-1 %).
MergeReport merge_ensemble(const std::string& dir, double relative_half_width = 0.01);

}  // namespace swarmlab::ensemble
