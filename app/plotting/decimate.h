#pragma once
// Long time series thinned for drawing: a figure of a million steps needs a few thousand
// points, but its spikes must survive, or a noisy P(t) would look calm.

#include <cstddef>
#include <vector>

namespace swarmlab::plotting {

struct XY {
  std::vector<double> x, y;
};

/// At most max_points points of the series (x, y of equal length): it is cut into
/// max_points / 2 buckets of consecutive points, equal to within one point, and each keeps its
/// lowest and highest y, in their order. Series of at most max_points points, and any series
/// when max_points < 4, come back unchanged. The first and last points are kept only when
/// they are the extremes of their bucket.
XY decimated(const std::vector<double>& x, const std::vector<double>& y, std::size_t max_points);

}  // namespace swarmlab::plotting
