#include "access/announcement.h"

#include <doctest/doctest.h>

#include <string>

using namespace swarmlab;

namespace {

Situation four_masses() {
  Situation s;
  s.preset = "Four masses (paper Fig. 1)";
  s.playing = true;
  s.t = 12.5;
  return s;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace

TEST_CASE("describe: the preset, playing or paused, the time, P and T, the selection, errors") {
  Situation s = four_masses();
  CHECK(describe(s) == "Four masses (paper Fig. 1). Playing, t = 12.5.");
  s.playing = false;
  s.selected = 2;
  CHECK(describe(s) == "Four masses (paper Fig. 1). Paused, t = 12.5. Particle 3 selected.");
  s.P = 0.03125;
  s.T = 1.05;
  CHECK(contains(describe(s), "P = 0.03125, T = 1.05."));  // four digits, as the read-outs
  s.finished = true;
  CHECK(contains(describe(s), "Finished, t = 12.5."));
  s.error = "dt: must be positive";
  CHECK(describe(s).rfind("Error: dt: must be positive. Four masses", 0) == 0);
}

TEST_CASE("page title: Swarm Lab, the preset and what it does") {
  Situation s = four_masses();
  CHECK(page_title(s) == "Swarm Lab \u2014 Four masses (paper Fig. 1), playing");
  s.playing = false;
  CHECK(page_title(s) == "Swarm Lab \u2014 Four masses (paper Fig. 1), paused");
}

TEST_CASE("Announcer: speaks first, then at once on a change of state, not on every frame") {
  Announcer a;
  Situation s = four_masses();
  REQUIRE(a.next(s, 0.0));
  // Frames later, the time moved: nothing until the interval has passed.
  s.t = 12.6;
  CHECK_FALSE(a.next(s, 0.016));
  s.t = 13.0;
  CHECK_FALSE(a.next(s, Announcer::kTimeInterval - 0.1));
  // Pausing is said at once, with the time it paused at.
  s.playing = false;
  const auto paused = a.next(s, Announcer::kTimeInterval - 0.05);
  REQUIRE(paused);
  CHECK(contains(*paused, "Paused, t = 13."));
  // Paused, the time does not move: silence however long it waits.
  CHECK_FALSE(a.next(s, 100.0));
  // A new preset and a selection are said at once.
  s.preset = "Gas in a sphere";
  const auto opened = a.next(s, 100.01);
  REQUIRE(opened);
  CHECK(contains(*opened, "Gas in a sphere."));
  s.selected = 0;
  const auto picked = a.next(s, 100.02);
  REQUIRE(picked);
  CHECK(contains(*picked, "Particle 1 selected."));
}

TEST_CASE("Announcer: while playing, the time is said again once per interval") {
  Announcer a;
  Situation s = four_masses();
  REQUIRE(a.next(s, 0.0));
  int said = 0;
  // 20 s of frames at 60 Hz, the simulated time running: four or five updates, not 1200.
  for (int frame = 1; frame <= 1200; ++frame) {
    s.t = 12.5 + frame / 60.0;
    if (a.next(s, frame / 60.0)) ++said;
  }
  CHECK(said == int(20 / Announcer::kTimeInterval));
}

TEST_CASE("Announcer: a lesson's new words are said at once, before the rest") {
  Announcer a;
  Situation s = four_masses();
  REQUIRE(a.next(s, 0.0));
  s.lesson = "One period, step 2 of 7. Press Play. How long is one turn?";
  s.lesson_place = "one-period/1";
  const auto step = a.next(s, 0.1);
  REQUIRE(step);
  CHECK(*step == s.lesson);  // only the lesson changed: only it is said
  CHECK_FALSE(a.next(s, 0.2));
  s.lesson = "Right: the period is 2 pi / sqrt(J M).";
  s.lesson_turn = 1;
  s.playing = false;  // an answer may change the scene too: said after the lesson's words
  const auto feedback = a.next(s, 0.3);
  REQUIRE(feedback);
  CHECK(feedback->rfind(s.lesson + " Four masses (paper Fig. 1). Paused", 0) == 0);
  s.lesson.clear();  // leaving a lesson says nothing by itself
  s.lesson_place.clear();
  CHECK_FALSE(a.next(s, 0.4));
}

TEST_CASE("Announcer: the same feedback to a new answer is said again, once") {
  Announcer a;
  Situation s = four_masses();
  s.lesson = "Not yet: the period is longer.";
  s.lesson_place = "one-period/1";
  s.lesson_turn = 1;
  REQUIRE(a.next(s, 0.0));
  CHECK_FALSE(a.next(s, 0.1));
  s.lesson_turn = 2;  // the same wrong number typed again
  const auto again = a.next(s, 0.2);
  REQUIRE(again);
  CHECK(*again == s.lesson);
  CHECK_FALSE(a.next(s, 0.3));
}

TEST_CASE("Announcer: a step is not said again when only its words for the device change") {
  Announcer a;
  Situation s = four_masses();
  s.lesson = "One period, step 4 of 7. Press Space to pause.";
  s.lesson_place = "one-period/3";
  REQUIRE(a.next(s, 0.0));
  s.lesson = "One period, step 4 of 7. Click the pause button to pause.";  // the mouse took over
  CHECK_FALSE(a.next(s, 0.1));
  s.lesson_place = "one-period/4";  // the next step is said
  REQUIRE(a.next(s, 0.2));
}

TEST_CASE("Announcer: a notice is said once, first, and not with every update after it") {
  Announcer a;
  Situation s = four_masses();
  REQUIRE(a.next(s, 0.0));
  s.notice = "Your lesson progress cannot be saved here.";
  const auto first = a.next(s, 0.1);
  REQUIRE(first);
  CHECK(*first == s.notice);  // only the notice is new: only it is said
  int repeated = 0, said = 0;
  for (int frame = 1; frame <= 1200; ++frame) {  // 20 s playing, then a pause
    s.t = 12.5 + frame / 60.0;
    s.playing = frame < 1200;
    if (const auto text = a.next(s, 0.1 + frame / 60.0)) {
      ++said;
      repeated += contains(*text, s.notice);
    }
  }
  CHECK(said >= 4);
  CHECK(repeated == 0);
  // A new notice comes before what else changed.
  s.notice = "Your saved lesson progress could not be read.";
  s.playing = true;
  const auto second = a.next(s, 30.0);
  REQUIRE(second);
  CHECK(second->rfind(s.notice + " Four masses (paper Fig. 1). Playing", 0) == 0);
}
