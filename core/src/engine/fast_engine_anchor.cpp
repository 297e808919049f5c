#include "engine/fast_engine_anchor.h"

#include <algorithm>

namespace swarm::fast {
namespace {

// A margin's width beyond the anchor's current offset, as a fraction of the wall radius, at
// least; and how many time units 1 / sqrt|k| of CM drift it should absorb.
constexpr double kMarginFloor = 0.004;
constexpr double kMarginDriftTimes = 4;
// At most N / kShellBudget particles within reach of a widened margin (J > 0).
constexpr std::size_t kShellBudget = 100;
// A moving wall spends an anchor's margin (Anchor::margin_at), which is renewed at half of it:
// it should last this many steps of the wall's travel, so that new anchors (and for J >= 0
// their re-bases, O(N)) stay rare.
constexpr double kMarginWallSteps = 512;

}  // namespace

Anchor anchor_with_margin(Anchor anchor, const Vec3& offset, const MarginInputs& in) {
  const double base = offset.norm();
  const double Rw = in.R;
  constexpr int kBins = GapHistogram::kBins;
  double extra = kMarginFloor * Rw;
  if (in.k != 0) extra = std::max(extra, kMarginDriftTimes * in.cm_speed / in.omega);
  extra = std::max(extra, kMarginWallSteps * in.wall_step);
  if (in.k > 0) {
    const std::size_t budget = std::max<std::size_t>(64, in.particles / kShellBudget);
    std::size_t within = 0;
    int bin = 0;
    while (bin < kBins && within + in.gaps->counts[std::size_t(bin)] <= budget)
      within += in.gaps->counts[std::size_t(bin++)];
    extra = std::max(extra, 0.5 * Rw * bin / kBins);
  }
  extra = std::min(extra, 0.5 * Rw);
  anchor.margin = base + extra;
  anchor.radius = Rw;
  anchor.threshold = Rw - anchor.margin;
  anchor.threshold2 = anchor.threshold * anchor.threshold;
  anchor.renew_level = base + 0.5 * extra;
  if (in.floor) {
    anchor.floor_low = offset.z() - extra;
    anchor.floor_renew = offset.z() - 0.5 * extra;
  }
  return anchor;
}

void Anchors::move_all_to_current(const std::vector<std::size_t>& lane_sizes) {
  old_.clear();
  std::fill(anchor_of_.begin(), anchor_of_.end(), current_.id);
  for (std::size_t lane = 0; lane < relying_.size(); ++lane) {
    relying_[lane].count.fill(0);
    relying_[lane].count[current_.id] = std::int32_t(lane_sizes[lane]);
  }
}

}  // namespace swarm::fast
