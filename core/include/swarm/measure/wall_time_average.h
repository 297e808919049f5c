#pragma once
/// A run's wall pressure and temperature as single numbers with honest errors: averaged over
/// the run's sample intervals from its equilibration start on, each with its blocking error
/// (swarm/measure/blocking.h), since neighbouring intervals are correlated.

#include <optional>
#include <vector>

#include "swarm/measure/blocking.h"
#include "swarm/measure/thermometry.h"
#include "swarm/measure/virial_balance.h"

namespace swarm {

struct WallTimeAverages {
  /// When the averaging starts (time): the start of the interval from which on the pressure's
  /// tail holds the most independent values (Chodera, J. Chem. Theory Comput. 12, 1799
  /// (2016)), tried at every twentieth of the run up to its middle. A run still settling
  /// gives a later start; one in equilibrium from the start keeps it. Given the run's virial
  /// terms, only starts whose window balances (virial_balance.h) are candidates; when none up
  /// to the middle does, the start whose imbalance is the fewest errors, and `virial` says by
  /// how much the run is too short to claim equilibrium.
  double start = 0;
  long intervals = 0;  ///< how many intervals the averages cover
  /// P over the time (each interval weighted by its length), T over the hits (weighted by
  /// them), as wall_average reads them; blocking_error's mean is the average. None with fewer
  /// than 8 intervals (for T: without hits).
  std::optional<BlockingError> P, T;
  /// The virial balance over the same window, when the run's terms were given.
  std::optional<VirialBalance> virial;
};

/// `virial`: the terms of the same intervals (virial_intervals, run.h), or none where the
/// balance does not apply (the start is then judged by P alone).
WallTimeAverages wall_time_averages(const std::vector<WallInterval>& intervals,
                                    const std::vector<VirialInterval>& virial = {});

}  // namespace swarm
