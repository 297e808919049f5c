#pragma once
/// A lab stopwatch on the simulated clock: it measures simulated time, so pausing the
/// simulation pauses it, and a faster playback speed runs it faster in wall time. The owner
/// tells it where the simulated clock is (observe) every frame; start, stop, lap and reset act
/// at the clock's current reading.

#include <optional>
#include <vector>

namespace swarm {

class Stopwatch {
 public:
  /// The simulated clock now reads t. Running, the stopwatch counts the time since the last
  /// reading; a clock that went back (a restarted run, a seek) adds nothing, so the reading
  /// never jumps by the size of the seek.
  void observe(double t);
  void start(double t);
  void stop(double t);
  /// Records the elapsed time now as a split (kept in order), and keeps running.
  void lap(double t);
  /// Stopped, at zero, no laps.
  void reset();

  bool running() const { return running_; }
  double elapsed() const { return elapsed_; }  ///< simulated time counted so far
  const std::vector<double>& laps() const { return laps_; }  ///< elapsed at each lap

 private:
  bool running_ = false;
  double elapsed_ = 0;
  double last_t_ = 0;  // the clock at the last observation
  std::vector<double> laps_;
};

/// A stretch of time in periods 2 pi / omega (omega = sqrt(k), k = J M): time omega / (2 pi).
/// None for k <= 0, where the motion has no period.
std::optional<double> in_periods(double time, double k);

}  // namespace swarm
