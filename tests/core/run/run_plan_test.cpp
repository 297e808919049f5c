#include "swarm/run/run_plan.h"

#include <doctest/doctest.h>

using namespace swarm;

TEST_CASE("an expansion stage lasts round(tau / dt) steps, at least one") {
  ExpansionProtocol e;
  e.tau = 100.0;
  CHECK(steps_per_stage(e, 0.01) == 10000);
  e.tau = 0.025;
  CHECK(steps_per_stage(e, 0.01) == 3);  // 2.5 rounds away from zero
  e.tau = 0.001;
  CHECK(steps_per_stage(e, 0.01) == 1);
}
