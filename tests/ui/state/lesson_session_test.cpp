#include "ui/state/lesson_session.h"

#include <doctest/doctest.h>

#include <cmath>
#include <memory>
#include <string>

#include "lessons/lesson_file.h"
#include "lessons/lesson_link.h"

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

TEST_CASE("lesson session: a step hides what gives its answer away until it is answered") {
  LessonSession session = loaded();
  const LessonScene scene = session.open(shipped_lesson(session, "one-period"));
  LiveRun run(*scene.preset_step->preset);
  CHECK_FALSE(session.hides(LessonHidden::readouts));  // step 1 asks nothing
  session.next();  // "How long is one turn?": the read-outs and the card show the period
  CHECK(session.hides(LessonHidden::readouts));
  CHECK(session.hides(LessonHidden::card));
  CHECK_FALSE(session.hides(LessonHidden::plots));
  session.answer_number(run, 1.0);  // wrong: still hidden
  CHECK(session.hides(LessonHidden::readouts));
  session.answer_number(run, session.reading(run));
  CHECK_FALSE(session.hides(LessonHidden::readouts));
  // The prediction step hides them until the prediction is made.
  session.next();
  CHECK(session.hides(LessonHidden::readouts));
  bool play = false;
  session.answer_option(2, &play);
  CHECK_FALSE(session.hides(LessonHidden::readouts));
}

TEST_CASE("lesson session: Finish shows a summary of each answer; Restart starts afresh") {
  LessonSession session = loaded();
  const Lesson& lesson = shipped_lesson(session, "springs-to-cm");
  session.open(lesson);
  bool play = false;
  session.answer_option(0, &play);  // step 1: wrong, then right
  session.answer_option(1, &play);
  session.go_to(1);
  session.answer_option(1, &play);  // a prediction
  session.go_to(lesson.steps.size() - 1);
  CHECK(progress_note(lesson, session.progress_of(lesson.id)) == "2/5 tasks");
  CHECK_FALSE(session.showing_summary());
  session.finish();
  CHECK(session.showing_summary());
  const LessonProgress& p = *session.progress_of(lesson.id);
  CHECK(p.finished);
  // Finished lessons do not look unfinished in the menu (finding 15).
  CHECK(progress_note(lesson, &p) == "done");
  REQUIRE(p.answers.count(0));
  CHECK(p.answers.at(0).answer == lesson.steps[0].task->options[1]);
  CHECK(*p.answers.at(0).correct);
  CHECK(p.answers.at(0).tries == 2);
  REQUIRE(p.answers.count(1));
  CHECK_FALSE(p.answers.at(1).correct);  // recorded, not marked
  CHECK(session.answered_count() == 2);
  CHECK(session.task_count() == 5);
  // The next shipped lesson in order.
  REQUIRE(session.next_lesson());
  CHECK(session.next_lesson()->id == "repulsive-runaway");
  // Restart: step 1, its preset again, nothing answered.
  const LessonScene again = session.restart();
  CHECK_FALSE(session.showing_summary());
  CHECK(session.step() == 0);
  CHECK(again.preset_step == again.step);
  CHECK(session.progress_of(lesson.id)->answers.empty());
  CHECK_FALSE(session.progress_of(lesson.id)->finished);
}

TEST_CASE("lesson session: answers and the finish are kept over visits") {
  LessonSession first = loaded();
  std::string saved;
  {
    auto store = make_memory_progress_store();
    ProgressStore* raw = store.get();
    first.load(SWARM_LESSON_DIR, std::move(store), shipped_preset_lookup(SWARM_PRESET_DIR));
    const Lesson& lesson = shipped_lesson(first, "springs-to-cm");
    first.open(lesson);
    bool play = false;
    first.answer_option(1, &play);
    first.finish();
    saved = raw->load();
  }
  LessonSession again = loaded(saved);
  const LessonProgress* p = again.progress_of("springs-to-cm");
  REQUIRE(p);
  CHECK(p->finished);
  REQUIRE(p->answers.count(0));
  CHECK(*p->answers.at(0).correct);
}

TEST_CASE("lesson session: Share links a shipped lesson by id and a lesson from a link by its JSON") {
  LessonSession session = loaded();
  CHECK(session.share_fragment().empty());
  session.open(shipped_lesson(session, "one-period"));
  CHECK(session.share_fragment() == "#lesson=one-period");
  CHECK(session.next_lesson() != nullptr);
  const std::string json =
      R"({"lesson": 1, "id": "mine", "title": "Mine", "summary": "A test.", "steps": [)"
      R"({"text": "Hello.", "preset": "two-body-circular.json"}]})";
  LessonScene scene;
  REQUIRE(session.open_json(json, &scene).empty());
  CHECK(session.share_fragment() == lesson_link_fragment("", json));
  CHECK(session.next_lesson() == nullptr);  // not one of the shipped row
}

namespace {

/// A session over `store` (kept by the caller, to look into).
LessonSession over(MemoryProgressStore* store) {
  LessonSession session;
  session.load(SWARM_LESSON_DIR, std::unique_ptr<ProgressStore>(store),
               shipped_preset_lookup(SWARM_PRESET_DIR));
  return session;
}

/// Answers the first option of lesson "springs-to-cm" (a recorded answer) and finishes it.
void make_progress(LessonSession& session) {
  session.open(shipped_lesson(session, "springs-to-cm"));
  bool play = false;
  session.answer_option(1, &play);
  session.finish();
}

}  // namespace

TEST_CASE("lesson session: progress that cannot be saved is said once, and still lasts the visit") {
  auto* store = new MemoryProgressStore();
  store->refuses = true;
  LessonSession session = over(store);
  // The first visit's save (the welcome seen) is refused: one notice.
  CHECK(session.progress_trouble() == ProgressTrouble::not_saved);
  CHECK(session.take_progress_notice());
  CHECK_FALSE(session.take_progress_notice());
  make_progress(session);
  CHECK_FALSE(session.take_progress_notice());  // said once, not at every change
  CHECK(store->text.empty());
  REQUIRE(session.progress_of("springs-to-cm"));
  CHECK(session.progress_of("springs-to-cm")->finished);
  // The file to download holds it, and loads again into a new visit.
  const std::string file = session.progress_json();
  LessonSession next = loaded();
  CHECK(next.progress_of("springs-to-cm") == nullptr);
  REQUIRE(next.load_progress_json(file).empty());
  REQUIRE(next.progress_of("springs-to-cm"));
  CHECK(next.progress_of("springs-to-cm")->finished);
  // Storage that takes it again: saved as usual, nothing more to say.
  store->refuses = false;
  session.restart();
  session.next();
  CHECK(session.progress_trouble() == ProgressTrouble::none);
  CHECK_FALSE(store->text.empty());
}

TEST_CASE("lesson session: a record that cannot be read is kept aside, never destroyed") {
  const std::string broken = R"({"version": 1, "welcomed": true, "lessons": {"springs-to-c)";
  auto* store = new MemoryProgressStore(broken);
  LessonSession session = over(store);
  CHECK(session.progress_trouble() == ProgressTrouble::unreadable_set_aside);
  REQUIRE(store->aside.size() == 1);
  CHECK(store->aside.begin()->second == broken);
  CHECK(session.progress_notice().find(store->aside.begin()->first) != std::string::npos);
  CHECK(session.take_progress_notice());
  // Lessons start afresh and are saved in its place.
  CHECK(session.show_welcome);
  CHECK(progress_record_kind(store->text) == ProgressRecordKind::readable);

  // Where it cannot even be copied aside, it is left where it is.
  auto* full = new MemoryProgressStore(broken);
  full->refuses = true;
  LessonSession left = over(full);
  CHECK(left.progress_trouble() == ProgressTrouble::unreadable_left);
  make_progress(left);
  CHECK(full->text == broken);
  CHECK(full->aside.empty());
}

TEST_CASE("lesson session: a newer version's record is left alone, and the welcome not shown again") {
  const std::string newer = R"({"version": 2, "welcomed": true, "lessons": {"x": {"stars": 3}}})";
  auto* store = new MemoryProgressStore(newer);
  LessonSession session = over(store);
  CHECK(session.progress_trouble() == ProgressTrouble::newer);
  CHECK(session.take_progress_notice());
  CHECK_FALSE(session.show_welcome);
  make_progress(session);
  CHECK(store->text == newer);  // progress made now lasts the visit
  CHECK(session.progress_of("springs-to-cm"));
  // A file from a newer build, or no progress at all, is refused with a reason.
  CHECK_FALSE(session.load_progress_json(newer).empty());
  CHECK_FALSE(session.load_progress_json("{\"preset\": 1}").empty());
  CHECK_FALSE(session.load_progress_json("not json").empty());
}

}  // namespace swarmlab
