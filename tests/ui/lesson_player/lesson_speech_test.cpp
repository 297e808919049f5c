#include "ui/lesson_player/lesson_speech.h"

#include <doctest/doctest.h>

#include <string>

#include "lessons/lesson_file.h"
#include "ui/state/lesson_session.h"
#include "ui/state/live_run.h"

namespace swarmlab {
namespace {

LessonSession shipped_session() {
  LessonSession session;
  session.load(SWARM_LESSON_DIR, make_memory_progress_store(),
               shipped_preset_lookup(SWARM_PRESET_DIR));
  return session;
}

const Lesson& one_period(const LessonSession& session) {
  const Lesson* found = nullptr;
  for (const Lesson& l : session.shipped())
    if (l.id == "one-period") found = &l;
  REQUIRE(found);
  return *found;
}

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace

TEST_CASE("lesson speech: the welcome names every lesson") {
  LessonSession session = shipped_session();
  session.show_welcome = true;
  const std::string words = lesson_speech(session, InputKind::keyboard).words;
  CHECK(words.rfind("Welcome to Swarm Lab.", 0) == 0);
  for (const Lesson& l : session.shipped()) CHECK(has(words, l.title));
  session.open(one_period(session));  // from the Lessons menu, the welcome still open
  CHECK(lesson_speech(session, InputKind::keyboard).words.rfind("One period", 0) == 0);
  session.close();
  session.show_welcome = false;
  CHECK(lesson_speech(session, InputKind::keyboard).words.empty());  // no lesson: nothing
}

TEST_CASE("lesson speech: a step is read with its place, its text, its question and options") {
  LessonSession session = shipped_session();
  const Lesson& lesson = one_period(session);
  session.open(lesson);
  session.go_to(3);  // "{Tap|Click} each ball in turn ..."
  const LessonStep& step = lesson.steps[3];
  const std::string touch = lesson_speech(session, InputKind::touch).words;
  CHECK(touch.rfind(lesson.title + ", step 4 of " + std::to_string(lesson.steps.size()) + ".", 0) ==
        0);
  CHECK(has(touch, "Tap each ball"));
  CHECK(has(lesson_speech(session, InputKind::mouse).words, "Click each ball"));
  CHECK_FALSE(has(touch, "*"));  // emphasis marks are not read
  CHECK_FALSE(has(touch, "{"));
  REQUIRE(step.task);
  CHECK(has(touch, step.task->prompt.substr(0, 20)));

  session.go_to(4);  // a choice: every option with its letter
  const LessonStep& choice = lesson.steps[4];
  REQUIRE(choice.task);
  const std::string read = lesson_speech(session, InputKind::keyboard).words;
  for (std::size_t k = 0; k < choice.task->options.size(); ++k)
    CHECK(has(read, std::string("Pick ") + char('A' + k) + ": "));
}

TEST_CASE("lesson speech: an answer is followed by its feedback, a new try by a new turn") {
  LessonSession session = shipped_session();
  const LessonScene scene = session.open(one_period(session));
  LiveRun run(*scene.preset_step->preset);
  session.next();  // "How long is one turn?"
  const LessonSpeech before = lesson_speech(session, InputKind::keyboard);
  const Marking wrong = session.answer_number(run, 100.0);
  const LessonSpeech first = lesson_speech(session, InputKind::keyboard);
  CHECK(first.words == wrong.feedback);
  CHECK(first.turn != before.turn);
  session.answer_number(run, 100.0);  // the same wrong number again: the same words, a new turn
  const LessonSpeech second = lesson_speech(session, InputKind::keyboard);
  CHECK(second.words == first.words);
  CHECK(second.turn != first.turn);

  CHECK(first.place == second.place);

  session.go_to(session.open_lesson()->steps.size() - 1);
  session.finish();
  const LessonSpeech summary = lesson_speech(session, InputKind::keyboard);
  CHECK(has(summary.words, "summary. " + session.finished_line()));
  CHECK(summary.place == "one-period/summary");
}

TEST_CASE(
    "lesson speech: a step whose prediction was made reads it and the outcome, not the options") {
  LessonSession session = shipped_session();
  const Lesson& lesson = one_period(session);
  session.open(lesson);
  session.go_to(2);  // predict: four masses
  const LessonTask& task = *lesson.steps[2].task;
  REQUIRE(task.kind == LessonTask::Kind::predict);
  CHECK(has(lesson_speech(session, InputKind::mouse).words, "Predict A: "));
  bool play = false;
  session.answer_option(1, &play);
  session.next();
  session.back();  // back on the step: the panel shows the prediction, so does the speech
  const std::string words = lesson_speech(session, InputKind::mouse).words;
  CHECK(has(words, "Your prediction: " + task.options[1].substr(0, 15)));
  CHECK_FALSE(has(words, "Predict A: "));
  if (!task.outcome.empty()) CHECK(has(words, "Now compare: "));
}

}  // namespace swarmlab
