// FrameDemand: when the window draws and when it idles.
#include "ui/frame_demand.h"

#include <doctest/doctest.h>

using swarmlab::FrameDemand;

namespace {

/// Draws frames at 60 per second from `t` for as long as the demand wants them (at most
/// `limit`); returns how many were drawn. Nothing moves and no text field is edited.
int frames_until_idle(FrameDemand& demand, double& t, int limit = 100) {
  int drawn = 0;
  while (drawn < limit && demand.wanted(t)) {
    demand.drawn(t, /*moving=*/false, /*editing=*/false);
    ++drawn;
    t += 1.0 / 60;
  }
  return drawn;
}

}  // namespace

TEST_CASE("frame_demand: a playing run draws every frame, and a paused one settles and idles") {
  FrameDemand demand;
  double t = 100;
  for (int i = 0; i < 10; ++i, t += 1.0 / 60) {
    REQUIRE(demand.wanted(t));
    demand.drawn(t, /*moving=*/true, false);
  }
  // Paused: the frame that stopped is followed by the settling frames, then nothing.
  CHECK(frames_until_idle(demand, t) == 1 + FrameDemand::kSettleFrames);
  CHECK_FALSE(demand.wanted(t + 3600));
  CHECK(demand.seconds_to_next(t) > 3600);
}

TEST_CASE("frame_demand: a change from outside draws the settling frames again, and no more") {
  FrameDemand demand;
  double t = 0;
  frames_until_idle(demand, t);
  REQUIRE_FALSE(demand.wanted(t));
  demand.wake();
  CHECK(demand.seconds_to_next(t) == 0);
  CHECK(frames_until_idle(demand, t) == FrameDemand::kSettleFrames);
  // Wakes in a row (a drag's motion events) keep it drawing until the last one has settled.
  for (int i = 0; i < 30; ++i) {
    demand.wake();
    REQUIRE(demand.wanted(t));
    demand.drawn(t, false, false);
    t += 1.0 / 60;
  }
  CHECK(frames_until_idle(demand, t) == FrameDemand::kSettleFrames - 1);
}

TEST_CASE("frame_demand: an edited text field draws at the caret's pace, not every frame") {
  FrameDemand demand;
  double t = 10;
  demand.drawn(t, false, /*editing=*/true);
  frames_until_idle(demand, t);
  demand.drawn(t, false, /*editing=*/true);
  CHECK_FALSE(demand.wanted(t + 0.5 * FrameDemand::kCaretSeconds));
  CHECK(demand.seconds_to_next(t + 0.5 * FrameDemand::kCaretSeconds) ==
        doctest::Approx(0.5 * FrameDemand::kCaretSeconds));
  CHECK(demand.wanted(t + FrameDemand::kCaretSeconds));
  // Over ten seconds of editing with no keys: one frame per caret period.
  int drawn = 0;
  for (double now = t; now < t + 10; now += 1.0 / 60)
    if (demand.wanted(now)) {
      demand.drawn(now, false, true);
      ++drawn;
    }
  CHECK(drawn == doctest::Approx(10 / FrameDemand::kCaretSeconds).epsilon(0.1));
}

TEST_CASE("frame_demand: a run that stops by itself (its end, a seek done) settles like a change") {
  FrameDemand demand;
  double t = 0;
  demand.drawn(t, /*moving=*/true, false);
  frames_until_idle(demand, t);  // moving: wanted throughout, until the first still frame
  REQUIRE_FALSE(demand.wanted(t));
  demand.drawn(t, /*moving=*/true, false);
  t += 1.0 / 60;
  demand.drawn(t, /*moving=*/false, false);  // the frame in which the run ended
  t += 1.0 / 60;
  CHECK(frames_until_idle(demand, t) == FrameDemand::kSettleFrames);
}
