#include "ui/lesson_player/lesson_session.h"

#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "lessons/lesson_file.h"

namespace swarmlab {
namespace {

LessonSession loaded(std::string progress = {}) {
  LessonSession session;
  session.load(SWARM_LESSON_DIR, make_memory_progress_store(std::move(progress)),
               shipped_preset_lookup(SWARM_PRESET_DIR));
  return session;
}

const Lesson& shipped_lesson(const LessonSession& session, const std::string& id) {
  for (const Lesson& l : session.shipped())
    if (l.id == id) return l;
  FAIL("no shipped lesson " << id);
  throw;
}

}  // namespace

TEST_CASE("lesson session: a step's scene opens a preset only where the scene changes") {
  LessonSession session = loaded();
  const Lesson& lesson = shipped_lesson(session, "one-period");
  const LessonScene first = session.open(lesson);
  REQUIRE(first.step == &session.open_lesson()->steps[0]);
  REQUIRE(first.preset_step == first.step);
  CHECK(first.location == "my-two-body-circular.json");
  CHECK_FALSE(first.pause);

  // Step 2 times the orbit in the same scene: nothing to open.
  const LessonScene second = session.next();
  CHECK(second.step == &session.open_lesson()->steps[1]);
  CHECK(second.preset_step == nullptr);

  // Step 3 brings its own preset and asks for a prediction first: the clock waits.
  const LessonScene third = session.next();
  REQUIRE(third.preset_step == third.step);
  CHECK(third.location == "my-fig1-four-masses.json");
  CHECK(third.pause);
  bool play = false;
  session.answer_option(0, &play);
  CHECK(play);
  // With the prediction made, coming back to the step does not pause again; going back to the
  // first scene opens its preset again.
  CHECK_FALSE(session.go_to(2).pause);
  CHECK(session.back().preset_step == &session.open_lesson()->steps[0]);
}

TEST_CASE("lesson session: a measured period is marked against the running system's 2 pi / sqrt(J M)") {
  LessonSession session = loaded();
  const Lesson& lesson = shipped_lesson(session, "one-period");
  const LessonScene scene = session.open(lesson);
  LiveRun run(*scene.preset_step->preset);
  session.next();  // "How long is one turn?"
  const double period = 2 * M_PI / std::sqrt(1.0 * (1.0 + 1.0));
  CHECK(session.reading(run) == doctest::Approx(period).epsilon(1e-12));
  const Marking right = session.answer_number(run, period * 1.01);
  REQUIRE(right.correct);
  CHECK(*right.correct);
  const Marking wrong = session.answer_number(run, period * 1.5);
  REQUIRE(wrong.correct);
  CHECK_FALSE(*wrong.correct);
  CHECK(session.progress_of("one-period")->solved.count(1) == 1);
}

TEST_CASE("lesson session: a lesson opens where the student left it") {
  LessonSession first = loaded();
  const LessonScene scene = first.open(shipped_lesson(first, "one-period"));
  REQUIRE(scene.step);
  first.go_to(3);
  REQUIRE(first.progress_of("one-period")->step == 3);
  // The step reached is kept: a session with the same progress reopens there, with the scene
  // of the last step before it that has a preset.
  std::string saved = R"({"version": 1, "welcomed": true, "lessons": {"one-period":
      {"step": 3, "solved": [], "predicted": {}}}})";
  LessonSession again = loaded(saved);
  const LessonScene resumed = again.open(shipped_lesson(again, "one-period"));
  CHECK(again.step() == 3);
  REQUIRE(resumed.preset_step);
  CHECK(resumed.location == "my-fig1-four-masses.json");
}

}  // namespace swarmlab
