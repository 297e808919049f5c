#include "ui/time/timeline_scale.h"

#include <doctest/doctest.h>

#include <initializer_list>

using namespace swarmlab;

TEST_CASE("timeline_scale: the pointer's x maps linearly to the run's steps, edges clamped") {
  // A bar from x = 100 to x = 500 over a run of 2000 steps (t = 20 at dt = 0.01).
  const TimelineScale scale{100, 500, 2000};
  CHECK(scale.step_at(100) == 0);
  CHECK(scale.step_at(500) == 2000);
  CHECK(scale.step_at(300) == 1000);
  // The finding's drag: the pointer over t = 2.65 puts the run at step 265 (t = 2.65), 53 px
  // from the left edge (400 px for 20 time units).
  CHECK(scale.step_at(100 + 400 * 2.65f / 20) == 265);
  CHECK(scale.step_at(40) == 0);      // left of the bar
  CHECK(scale.step_at(900) == 2000);  // right of it
  // Half a step's width rounds to the nearest step.
  CHECK(scale.step_at(100 + 0.3f * 0.2f) == 0);
  CHECK(scale.step_at(100 + 0.7f * 0.2f) == 1);
}

TEST_CASE("timeline_scale: a step drawn at x_of is found again under the pointer there") {
  const TimelineScale scale{12.5f, 377.5f, 4321};
  for (long step : {0L, 1L, 17L, 999L, 2160L, 4320L, 4321L})
    CHECK(scale.step_at(scale.x_of(step)) == step);
  CHECK(scale.x_of(0) == doctest::Approx(12.5));
  CHECK(scale.x_of(4321) == doctest::Approx(377.5));
}

TEST_CASE("timeline_scale: a drag scrubs within the time computed, a press goes anywhere") {
  CHECK(TimelineScale::scrub_target(1500, true, 800) == 1500);  // computes up to there
  CHECK(TimelineScale::scrub_target(1500, false, 800) == 800);  // a drag stops at the edge
  CHECK(TimelineScale::scrub_target(265, false, 813) == 265);   // back in time: exactly there
}
