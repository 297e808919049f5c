#include "swarm/run/run_plan.h"

#include <algorithm>
#include <cmath>

namespace swarm {

long steps_per_stage(const ExpansionProtocol& e, double dt) {
  return std::max(1L, std::lround(e.tau / dt));
}

}  // namespace swarm
