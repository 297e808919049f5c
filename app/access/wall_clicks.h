#pragma once
// Hearing the wall: each wall hit a click, thinned so that a swarm hitting the wall thousands of
// times a second is still heard as separate clicks whose rate rises with the hit rate, the way
// a Geiger counter makes pressure audible.

#include <cstdint>

namespace swarmlab {

class WallClicks {
 public:
  /// Every hit is heard up to this rate (clicks per second of wall time).
  static constexpr double kEveryHitUpTo = 20;
  /// Above it the clicks rise as the logarithm of the hit rate, up to this many per second.
  static constexpr double kMaxClickRate = 60;
  /// The hit rate heard is averaged over about this long (seconds), so one frame's burst does
  /// not decide.
  static constexpr double kRateMemory = 0.5;

  /// Clicks per second heard at a steady hit rate (hits per second): the rate itself up to
  /// kEveryHitUpTo, then kEveryHitUpTo * (1 + ln(rate / kEveryHitUpTo) / 2), at most
  /// kMaxClickRate. Rises with the hit rate everywhere below the cap.
  static double click_rate(double hit_rate);

  /// The clicks to play for a frame of `seconds` of wall time in which `hits` wall hits were
  /// made; fractions of a click are carried to the next frame.
  int clicks(std::int64_t hits, double seconds);
  /// Forgets the rate and the carried fraction (sound turned on, a new run).
  void reset() { hit_rate_ = 0, owed_ = 0; }
  double hit_rate() const { return hit_rate_; }

 private:
  double hit_rate_ = 0;  ///< smoothed, hits per second
  double owed_ = 0;      ///< fraction of a click carried over
};

}  // namespace swarmlab
