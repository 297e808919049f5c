#include "access/wall_clicks.h"

#include <algorithm>
#include <cmath>

namespace swarmlab {

double WallClicks::click_rate(double hit_rate) {
  if (!(hit_rate > 0)) return 0;
  if (hit_rate <= kEveryHitUpTo) return hit_rate;
  return std::min(kMaxClickRate, kEveryHitUpTo * (1 + 0.5 * std::log(hit_rate / kEveryHitUpTo)));
}

int WallClicks::clicks(std::int64_t hits, double seconds) {
  if (!(seconds > 0) || hits < 0) return 0;
  hit_rate_ += (1 - std::exp(-seconds / kRateMemory)) * (double(hits) / seconds - hit_rate_);
  // Each hit is kept with the probability that the heard rate allows at the current hit rate;
  // a lone hit (a low rate) is always kept.
  const double kept = hit_rate_ > 0 ? std::min(1.0, click_rate(hit_rate_) / hit_rate_) : 1.0;
  owed_ += double(hits) * kept;
  // No burst after a stall: at most what the cap allows in this frame (and at least one).
  const double most = std::max(1.0, std::ceil(kMaxClickRate * seconds));
  const double n = std::min(std::floor(owed_), most);
  owed_ = std::min(owed_ - n, 1.0);
  return int(n);
}

}  // namespace swarmlab
