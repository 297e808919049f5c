#pragma once
// A progress bar on stderr for runs that take longer than a second.

#include <chrono>
#include <string>

namespace swarmlab {

class ProgressBar {
 public:
  explicit ProgressBar(std::string label, bool enabled = true);
  /// fraction in [0, 1]; draws at most ten times a second, and only after the first second.
  void update(double fraction);
  /// Completes the line if anything was drawn.
  void finish();

 private:
  std::string label_;
  bool enabled_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_, last_draw_;
};

}  // namespace swarmlab
