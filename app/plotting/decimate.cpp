#include "decimate.h"

#include <algorithm>

namespace swarmlab::plotting {

XY decimated(const std::vector<double>& x, const std::vector<double>& y, std::size_t max_points) {
  const std::size_t n = x.size();
  if (n <= max_points || max_points < 4) return {x, y};
  const std::size_t buckets = max_points / 2;
  XY out;
  for (std::size_t b = 0; b < buckets; ++b) {
    const std::size_t begin = b * n / buckets, end = (b + 1) * n / buckets;
    std::size_t low = begin, high = begin;
    for (std::size_t i = begin; i < end; ++i) {
      if (y[i] < y[low]) low = i;
      if (y[i] > y[high]) high = i;
    }
    for (std::size_t i : {std::min(low, high), std::max(low, high)}) {
      out.x.push_back(x[i]);
      out.y.push_back(y[i]);
      if (low == high) break;
    }
  }
  return out;
}

}  // namespace swarmlab::plotting
