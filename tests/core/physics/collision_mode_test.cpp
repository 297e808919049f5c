#include "swarm/physics/collision_mode.h"

#include <doctest/doctest.h>

using namespace swarm;

TEST_CASE("collision modes round-trip through their preset names, and nothing else parses") {
  for (CollisionMode c : {CollisionMode::paper, CollisionMode::exact})
    CHECK(collision_mode_named(name_of(c)) == c);
  CHECK_FALSE(collision_mode_named("Paper").has_value());
  CHECK_FALSE(collision_mode_named("").has_value());
}
