// The C side of the lesson calls of window.swarmlab (lessons, openLesson, lessonState,
// lessonAnswer, lessonNext, lessonBack, lessonLink in web/swarmlab_api.js), the #lesson= link,
// the lesson panel's Share button, and the progress loaded again from a file.

#include <emscripten.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "i18n/translator.h"
#include "lessons/device_words.h"
#include "lessons/lesson.h"
#include "lessons/lesson_link.h"
#include "ui/lesson_player/input_kind.h"
#include "ui/lesson_player/lesson_scene.h"
#include "web_app.h"

// The Share button: the page makes the link from the fragment, copies it and shows it.
EM_JS(void, js_share_lesson, (const char* fragment),
      { Module.swarmlab.shareLesson(UTF8ToString(fragment)); });

// Load progress...: a file picker (swarmlab_api.js), whose text comes back to
// swarmlab_load_progress.
EM_JS(void, js_pick_progress_file, (), { Module.swarmlab.pickProgressFile(); });

namespace {

using json = nlohmann::json;
std::string lessons_text, lesson_open_error, lesson_state_text, answer_text,
    fragment_text;  // valid until the next call

/// Shows a refused lesson in the lesson panel and the scenario panel; returns it.
const std::string& refuse_lesson(swarmlab::AppState& s, std::string error) {
  s.lessons.error = error;
  s.status = error;
  s.status_is_error = true;
  lesson_open_error = std::move(error);
  return lesson_open_error;
}

/// Feedback as the lesson panel shows it to this student: in the language in use, the device's
/// words chosen ({tap|click} read for the input used last), without the *emphasis* marks.
std::string plain_feedback(const swarmlab::AppState& app, const std::string& feedback) {
  return swarmlab::without_emphasis(
      swarmlab::device_words(swarmlab::tr(feedback.c_str()), swarmlab::input_kind(app)));
}

json number_or_null(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }

json lesson_state(swarmlab::AppState& app) {
  swarmlab::LessonSession& lessons = app.lessons;
  const swarmlab::Lesson* lesson = lessons.open_lesson();
  if (!lesson) return nullptr;
  const swarmlab::LessonStep& step = *lessons.current_step();
  json task = nullptr;
  if (step.task) {
    const swarmlab::LessonTask& t = *step.task;
    task = {{"kind", std::string(swarmlab::name_of(t.kind))}, {"prompt", t.prompt}};
    if (t.kind == swarmlab::LessonTask::Kind::measure) {
      task["quantity"] = std::string(swarmlab::name_of(t.quantity));
      task["tolerance"] = t.tolerance;
      task["particle"] = t.particle ? json(*t.particle) : json(nullptr);
      if (t.window > 0) task["window"] = t.window;
      // What the app's instruments read for the quantity now (the read-outs, the wall plot).
      task["reading"] = number_or_null(lessons.reading(*app.run));
    } else {
      task["options"] = t.options;
    }
    if (t.kind == swarmlab::LessonTask::Kind::predict) {
      const auto p = lessons.prediction();
      task["prediction"] = p ? json(*p) : json(nullptr);
      task["outcome"] = t.outcome;
    }
    if (const auto& m = lessons.marking())
      task["answered"] = {{"correct", m->correct ? json(*m->correct) : json(nullptr)},
                          {"feedback", plain_feedback(app, m->feedback)}};
    else
      task["answered"] = nullptr;
  }
  return {{"id", lesson->id},
          {"title", lesson->title},
          {"step", lessons.step()},
          {"steps", lesson->steps.size()},
          {"text", step.text},
          {"task", task},
          {"summary", lessons.showing_summary()},
          {"hidden", {{"readouts", lessons.hides(swarmlab::LessonHidden::readouts)},
                      {"card", lessons.hides(swarmlab::LessonHidden::card)},
                      {"plots", lessons.hides(swarmlab::LessonHidden::plots)}}},
          {"loops", app.lesson_loops}};
}

}  // namespace

extern "C" {

/// The shipped lessons as JSON: [{id, title, summary, steps}].
EMSCRIPTEN_KEEPALIVE const char* swarmlab_lessons() {
  json list = json::array();
  if (swarmlab::App* app = swarmlab::web_app())
    for (const swarmlab::Lesson& l : app->state().lessons.shipped())
      list.push_back({{"id", l.id}, {"title", l.title}, {"summary", l.summary},
                      {"steps", l.steps.size()}});
  lessons_text = list.dump();
  return lessons_text.c_str();
}

/// Whether JSON text of `bytes` bytes is a lesson (lesson.h's looks_like_lesson): 1 or 0. A
/// file picked or dropped on the page opens as a lesson when it is one.
EMSCRIPTEN_KEEPALIVE int swarmlab_is_lesson(const char* text, int bytes) {
  return swarmlab::looks_like_lesson(std::string_view(text, std::size_t(bytes))) ? 1 : 0;
}

/// Opens a lesson: `text` (`bytes` bytes, a NUL among them refused by the lesson's rule) is a
/// shipped lesson's id, or lesson JSON when `is_json`. "" on success, else "source: message"
/// (also shown in the app); the running lesson stays.
EMSCRIPTEN_KEEPALIVE const char* swarmlab_open_lesson(const char* text, int bytes, int is_json,
                                                      const char* source) {
  swarmlab::App* app = swarmlab::web_app();
  if (!app) return "the app has not started";
  swarmlab::AppState& s = app->state();
  const std::string given(text, std::size_t(bytes));
  std::string error = is_json ? swarmlab::open_lesson_json(s, given) : swarmlab::open_lesson_id(s, given);
  if (!error.empty()) return refuse_lesson(s, std::string(source) + ": " + error).c_str();
  s.lessons.error.clear();
  s.lessons.dismiss_welcome();
  lesson_open_error.clear();
  return lesson_open_error.c_str();
}

/// Opens what a #lesson= link holds (the text after "#lesson=", lesson_link.h): a shipped
/// lesson's id or a lesson's JSON in base64url. "" on success, else "lesson link: ..." (also
/// shown in the app); the running lesson stays.
EMSCRIPTEN_KEEPALIVE const char* swarmlab_open_lesson_link(const char* value) {
  swarmlab::App* app = swarmlab::web_app();
  if (!app) return "the app has not started";
  swarmlab::AppState& s = app->state();
  std::vector<std::string> ids;
  for (const swarmlab::Lesson& l : s.lessons.shipped()) ids.push_back(l.id);
  const swarmlab::LessonLinkTarget target = swarmlab::read_lesson_link(value, ids);
  std::string error = target.error;
  if (error.empty())
    error = target.id.empty() ? swarmlab::open_lesson_json(s, target.json)
                              : swarmlab::open_lesson_id(s, target.id);
  if (!error.empty()) return refuse_lesson(s, "lesson link: " + error).c_str();
  s.lessons.error.clear();
  s.lessons.dismiss_welcome();
  lesson_open_error.clear();
  return lesson_open_error.c_str();
}

/// The link fragment ("#lesson=...") that opens the open lesson, "" when none is open.
EMSCRIPTEN_KEEPALIVE const char* swarmlab_lesson_fragment() {
  swarmlab::App* app = swarmlab::web_app();
  fragment_text = app ? app->state().lessons.share_fragment() : std::string();
  return fragment_text.c_str();
}

/// The open lesson's state as JSON, "null" when none is open.
EMSCRIPTEN_KEEPALIVE const char* swarmlab_lesson_state() {
  swarmlab::App* app = swarmlab::web_app();
  lesson_state_text = app ? lesson_state(app->state()).dump() : "null";
  return lesson_state_text.c_str();
}

/// Answers the current task: a number for measure, an option's index for choice and predict.
/// {correct, feedback}, or {error} when no lesson or no task is open.
EMSCRIPTEN_KEEPALIVE const char* swarmlab_lesson_answer(double value) {
  json out;
  swarmlab::App* app = swarmlab::web_app();
  const swarmlab::LessonStep* step = app ? app->state().lessons.current_step() : nullptr;
  if (!step) {
    out = {{"error", "no lesson is open"}};
  } else if (!step->task) {
    out = {{"error", "this step has no task"}};
  } else if (step->task->kind != swarmlab::LessonTask::Kind::measure &&
             !(value >= 0 && value < double(step->task->options.size()) && value == std::floor(value))) {
    // Checked as a double: a size_t (32 bits in wasm) would take 2^32 + 1 as option 1.
    char text[160];
    std::snprintf(text, sizeof text, "value must be an option's index, an integer from 0 to %zu, not %.17g",
                  step->task->options.size() - 1, value);
    out = {{"error", text}};
  } else {
    swarmlab::AppState& s = app->state();
    const swarmlab::Marking m = step->task->kind == swarmlab::LessonTask::Kind::measure
                                    ? s.lessons.answer_number(*s.run, value)
                                    : swarmlab::answer_lesson_option(s, std::size_t(value));
    out = {{"correct", m.correct ? json(*m.correct) : json(nullptr)},
           {"feedback", plain_feedback(s, m.feedback)}};
  }
  answer_text = out.dump();
  return answer_text.c_str();
}

/// Next (+1) or back (-1) a step; the lesson state afterwards.
EMSCRIPTEN_KEEPALIVE const char* swarmlab_lesson_move(int direction) {
  if (swarmlab::App* app = swarmlab::web_app()) {
    swarmlab::AppState& s = app->state();
    if (direction > 0)
      swarmlab::show_lesson_scene(s, s.lessons.next());
    else
      swarmlab::show_lesson_scene(s, s.lessons.back());
  }
  return swarmlab_lesson_state();
}

/// The Finish button (+1: the summary) or Restart lesson (-1: step 1, answers forgotten); the
/// lesson state afterwards.
EMSCRIPTEN_KEEPALIVE const char* swarmlab_lesson_finish(int finish) {
  if (swarmlab::App* app = swarmlab::web_app()) {
    swarmlab::AppState& s = app->state();
    if (finish > 0)
      s.lessons.finish();
    else
      swarmlab::show_lesson_scene(s, s.lessons.restart());
  }
  return swarmlab_lesson_state();
}

/// Whether the welcome window is showing (for tests of the first visit).
EMSCRIPTEN_KEEPALIVE int swarmlab_welcome_shown() {
  swarmlab::App* app = swarmlab::web_app();
  return app && app->state().lessons.show_welcome ? 1 : 0;
}

/// Progress from a file the student picked (Load progress...): {"loaded": true or false,
/// "message": what to say, in the language in use}, also put in the status line.
EMSCRIPTEN_KEEPALIVE const char* swarmlab_load_progress(const char* text) {
  static std::string answer;
  swarmlab::App* app = swarmlab::web_app();
  if (!app) return "{}";
  swarmlab::AppState& s = app->state();
  const std::string error = s.lessons.load_progress_json(text);
  s.status = error.empty() ? swarmlab::tr("Lesson progress loaded from the file.") : error;
  s.status_is_error = !error.empty();
  answer = json{{"loaded", error.empty()}, {"message", s.status}}.dump();
  return answer.c_str();
}

}  // extern "C"

void swarmlab::install_lesson_share(AppState& state) {
  state.lessons.share = [](const std::string& fragment) { js_share_lesson(fragment.c_str()); };
  state.lessons.pick_progress_file = [] { js_pick_progress_file(); };
}
