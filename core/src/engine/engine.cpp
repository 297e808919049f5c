#include "swarm/engine/engine.h"

#ifndef __EMSCRIPTEN__
#include <algorithm>
#include <thread>
#endif

#include "swarm/engine/fast_engine.h"

namespace swarm {

int default_threads() {
#ifndef __EMSCRIPTEN__
  // hardware_concurrency may say 0 when it cannot tell.
  static const int threads =
      std::min(kMaxThreads, int(std::max(1u, std::thread::hardware_concurrency())));
  return threads;
#else
  return 1;
#endif
}

std::unique_ptr<Engine> make_engine(System initial, const EngineConfig& config) {
  if (fast_engine_applies(config) && initial.particles.size() <= kMaxFastEngineParticles)
    return make_fast_engine(std::move(initial), config);
  return make_reference_engine(std::move(initial), config);
}

}  // namespace swarm
