#include "cli/progress_bar.h"

#include <cstdio>

namespace swarmlab {

ProgressBar::ProgressBar(std::string label, bool enabled)
    : label_(std::move(label)), enabled_(enabled), start_(std::chrono::steady_clock::now()) {}

void ProgressBar::update(double fraction) {
  if (!enabled_) return;
  using namespace std::chrono;
  const auto now = steady_clock::now();
  const double elapsed = duration<double>(now - start_).count();
  if (elapsed < 1.0 || (drawn_ && now - last_draw_ < milliseconds(100))) return;
  last_draw_ = now;
  drawn_ = true;
  constexpr int width = 40;
  const int filled = int(fraction * width + 0.5);
  const double eta = fraction > 0 ? elapsed * (1 - fraction) / fraction : 0;
  std::fprintf(stderr, "\r%s [%-*s] %5.1f%%  %.0f s left ", label_.c_str(), width,
               std::string(std::size_t(filled), '#').c_str(), 100 * fraction, eta);
  std::fflush(stderr);
}

void ProgressBar::finish() {
  if (enabled_ && drawn_) std::fprintf(stderr, "\n");
}

}  // namespace swarmlab
