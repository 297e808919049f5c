#pragma once
// Runs something step by step to its end in chunks of about a tenth of a second (doubled or
// halved as they come in short or long), so that whoever watches the progress hears from it
// at least once a second however long the run or a step. The numbers do not depend on the
// chunks: only how often progress is reported does.

#include <chrono>
#include <functional>

namespace swarm {

/// advance(n) takes up to n steps; finished() says when to stop; done() is the fraction done.
template <class Advance, class Finished, class Done>
void advance_to_end(Advance advance, Finished finished, Done done,
                    const std::function<void(double)>& progress) {
  using clock = std::chrono::steady_clock;
  long chunk = 1;
  while (!finished()) {
    const clock::time_point start = clock::now();
    advance(chunk);
    if (progress) progress(done());
    const double seconds = std::chrono::duration<double>(clock::now() - start).count();
    if (seconds < 0.05)
      chunk *= 2;
    else if (seconds > 0.2 && chunk > 1)
      chunk /= 2;
  }
}

}  // namespace swarm
