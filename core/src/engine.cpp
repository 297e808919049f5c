#include "swarm/engine.h"

#include "swarm/fast_engine.h"

namespace swarm {

std::unique_ptr<Engine> make_engine(System initial, const EngineConfig& config) {
  if (fast_engine_applies(config) && initial.particles.size() <= kMaxFastEngineParticles)
    return make_fast_engine(std::move(initial), config);
  return make_reference_engine(std::move(initial), config);
}

}  // namespace swarm
