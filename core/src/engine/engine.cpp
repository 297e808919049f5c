#include "swarm/engine/engine.h"

#ifndef __EMSCRIPTEN__
#include <thread>
#endif

#include "swarm/engine/fast_engine.h"

namespace swarm {

int default_threads() {
#ifndef __EMSCRIPTEN__
  static const int threads = std::thread::hardware_concurrency() >= 2 ? 2 : 1;
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
