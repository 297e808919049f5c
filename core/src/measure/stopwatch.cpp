#include "swarm/measure/stopwatch.h"

#include <cmath>

#include "swarm/physics/regime.h"

namespace swarm {

void Stopwatch::observe(double t) {
  if (running_ && t > last_t_) elapsed_ += t - last_t_;
  last_t_ = t;
}

void Stopwatch::start(double t) {
  observe(t);
  running_ = true;
}

void Stopwatch::stop(double t) {
  observe(t);
  running_ = false;
}

void Stopwatch::lap(double t) {
  observe(t);
  laps_.push_back(elapsed_);
}

void Stopwatch::reset() {
  running_ = false;
  elapsed_ = 0;
  laps_.clear();
}

std::optional<double> in_periods(double time, double k) {
  if (regime_of(k) != Regime::attractive) return std::nullopt;
  return time / period_of(k);
}

}  // namespace swarm
