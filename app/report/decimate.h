#pragma once
// Long time series thinned for drawing: a figure of a million steps needs a few thousand
// points, but its spikes must survive, or a noisy P(t) would look calm.

#include <vector>

namespace swarmlab::report {

struct XY {
  std::vector<double> x, y;
};

/// At most about max_points points: the series is cut into max_points / 2 buckets and each
/// keeps its lowest and highest y, in time order. Shorter series come back unchanged.
XY decimated(const std::vector<double>& x, const std::vector<double>& y, std::size_t max_points);

}  // namespace swarmlab::report
