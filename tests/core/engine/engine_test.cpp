// make_engine chooses the engine; the engines themselves have their own tests.

#include "swarm/engine/engine.h"

#include <doctest/doctest.h>

#include "swarm/engine/fast_engine.h"
#include "test_systems.h"

using namespace swarm;
using namespace swarm::testing;

TEST_CASE("make_engine picks the fast engine only where it applies") {
  const System s = crowded_swarm(10, 1.0, 1);
  CHECK(fast_engine_stats(*make_engine(s, {Method::analytic, CollisionMode::paper, 1.0})));
  CHECK_FALSE(fast_engine_stats(*make_engine(s, {Method::analytic, CollisionMode::exact, 1.0})));
  CHECK_FALSE(fast_engine_stats(*make_engine(s, {Method::verlet, CollisionMode::paper, 1.0})));
  CHECK_THROWS(make_fast_engine(s, {Method::rk4, CollisionMode::paper, 1.0}));
}

TEST_CASE("the default thread count is at least one, and one where there are no threads") {
  CHECK(default_threads() >= 1);
#ifdef __EMSCRIPTEN__
  CHECK(default_threads() == 1);
#endif
}
