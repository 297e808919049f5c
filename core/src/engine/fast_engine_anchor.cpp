#include "engine/fast_engine_anchor.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "swarm/physics/flow.h"

namespace swarm::fast {
namespace {

// A margin's width beyond the anchor's current offset, as a fraction of the wall radius, at
// least; and how many time units 1 / sqrt|k| of CM drift it should absorb.
constexpr double kMarginFloor = 0.004;
constexpr double kMarginDriftTimes = 4;
// An off-centre anchor's margin beyond its fit's residual (OffsetFit), for what the fit cannot
// foresee: the unsteady part of the wall's kicks. Measured on the gravity benchmark
// (bench/RESULTS.md) against slacks of 0.005 to 0.1 and the residual counted once or twice.
constexpr double kFitResidualTimes = 2;
constexpr double kFitSlack = 0.035;
// No margin is wider than this fraction of the wall radius.
constexpr double kMarginCap = 0.5;
// At most N / kShellBudget particles within reach of a widened margin (J > 0).
constexpr std::size_t kShellBudget = 100;
// A moving wall spends an anchor's margin (Anchor::margin_at), which is renewed at half of it:
// it should last this many steps of the wall's travel, so that new anchors (and for J >= 0
// their re-bases, O(N)) stay rare.
constexpr double kMarginWallSteps = 512;

}  // namespace

OffsetFit fit_offset_path(const Vec3& offset, const Vec3& v, const Vec3& acc, const Vec3& push,
                          double k, double horizon) {
  OffsetFit fit;
  fit.centre = offset;
  if (!(horizon > 0)) return fit;
  // P(tau) ~ alpha + beta (1 - xc) + gamma xs: the basis 1, 1 - cos, sin keeps the normal
  // equations well conditioned at short horizons (it is nearly 1, tau^2 / 2, tau). Then F's A =
  // -beta, B = gamma, and the centre is alpha + beta. For k = 0, xc = 1: F = B tau.
  constexpr int kSamples = 9;
  std::array<double, kSamples> u{}, s{};
  std::array<Vec3, kSamples> P{};
  for (int j = 0; j < kSamples; ++j) {
    const double tau = horizon * j / (kSamples - 1);
    const Flow f = Flow::over(k, tau);
    u[std::size_t(j)] = 1 - f.c;
    s[std::size_t(j)] = f.s;
    P[std::size_t(j)] = offset + tau * v + (0.5 * tau * tau) * acc;
    // A steady push a moves R_cm by a tau^2 / 2 and Y, which takes the same kicks, by
    // a (1 - cos) / k: the offset R_cm - Y by the difference (nothing when k = 0).
    if (k > 0) P[std::size_t(j)] += (0.5 * tau * tau - u[std::size_t(j)] / k) * push;
  }
  const bool oscillates = k > 0;
  double G[3][3] = {};
  Vec3 rhs[3] = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  for (std::size_t j = 0; j < kSamples; ++j) {
    const double phi[3] = {1, oscillates ? u[j] : 0.0, s[j]};
    for (int r = 0; r < 3; ++r) {
      rhs[r] += phi[r] * P[j];
      for (int c = 0; c < 3; ++c) G[r][c] += phi[r] * phi[c];
    }
  }
  if (!oscillates) G[1][1] = 1;  // beta = 0
  // Cramer's rule on the symmetric 3 x 3 system.
  const auto det3 = [](const double m[3][3]) {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
           m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  };
  const double det = det3(G);
  if (!(std::abs(det) > 0)) return fit;
  Vec3 coef[3];
  for (int col = 0; col < 3; ++col) {
    Vec3 out;
    for (int d = 0; d < 3; ++d) {
      double m[3][3];
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) m[r][c] = c == col ? rhs[r][d] : G[r][c];
      out[d] = det3(m) / det;
    }
    coef[col] = out;
  }
  fit.A = -coef[1];
  fit.B = coef[2];
  fit.centre = coef[0] + coef[1];
  for (std::size_t j = 0; j < kSamples; ++j)
    fit.residual = std::max(
        fit.residual, (P[j] - coef[0] - u[j] * coef[1] - s[j] * coef[2]).norm());
  return fit;
}

double largest_fit_residual(double R) { return (kMarginCap - kFitSlack) * R / kFitResidualTimes; }

Anchor anchor_with_margin(Anchor anchor, const Vec3& offset, const MarginInputs& in) {
  if (in.off_centre) anchor.centre = offset;
  const double base = in.off_centre ? 0.0 : offset.norm();
  const double Rw = in.R;
  constexpr int kBins = GapHistogram::kBins;
  double extra = kMarginFloor * Rw;
  if (in.off_centre)
    extra = std::max(extra, kFitResidualTimes * in.residual + kFitSlack * Rw);
  else if (in.k != 0)
    extra = std::max(extra, kMarginDriftTimes * in.cm_speed / in.omega);
  extra = std::max(extra, kMarginWallSteps * in.wall_step);
  if (in.k > 0 && !in.off_centre) {
    const std::size_t budget = std::max<std::size_t>(64, in.particles / kShellBudget);
    std::size_t within = 0;
    int bin = 0;
    while (bin < kBins && within + in.gaps->counts[std::size_t(bin)] <= budget)
      within += in.gaps->counts[std::size_t(bin++)];
    extra = std::max(extra, 0.5 * Rw * bin / kBins);
  }
  extra = std::min(extra, kMarginCap * Rw);
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
