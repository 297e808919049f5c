#include "ui/lesson_player/lesson_speech.h"

#include "ui/state/lesson_session.h"

#include <cstdio>

#include "i18n/printed.h"
#include "i18n/translator.h"

namespace swarmlab {
namespace {

/// A lesson's text as it is read: in the language in use (translated before its device words
/// are chosen, as the key holds the choices), emphasis marks dropped, paragraphs joined.
std::string plain(const std::string& text, InputKind input) {
  std::string out;
  for (const char c : without_emphasis(device_words(tr(text.c_str()), input))) {
    if (c == '\n') {
      if (!out.empty() && out.back() != ' ') out += ' ';
      continue;
    }
    out += c;
  }
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

/// Joins sentences with one space.
void add(std::string& to, const std::string& sentence) {
  if (sentence.empty()) return;
  if (!to.empty()) to += ' ';
  to += sentence;
}

std::string step_words(const LessonSession& lessons, InputKind input) {
  const Lesson& lesson = *lessons.open_lesson();
  const std::size_t i = lessons.step();
  const LessonStep& step = lesson.steps[i];
  std::string words =
      printed(tr("%s, step %zu of %zu."), tr(lesson.title.c_str()), i + 1, lesson.steps.size());
  add(words, plain(step.text, input));
  if (!step.task) return words;
  add(words, plain(step.task->prompt, input));
  const bool predict = step.task->kind == LessonTask::Kind::predict;
  if (predict && lessons.prediction()) {
    // Made on an earlier visit: the panel shows it and the outcome, not the options.
    add(words, printed(tr("Your prediction: %s."),
                        plain(step.task->options[*lessons.prediction()], input).c_str()));
    if (!step.task->outcome.empty())
      add(words, printed(tr("Now compare: %s"), plain(step.task->outcome, input).c_str()));
    return words;
  }
  for (std::size_t k = 0; k < step.task->options.size(); ++k)
    add(words, printed(predict ? tr("Predict %c: %s.") : tr("Pick %c: %s."), char('A' + k),
                        plain(step.task->options[k], input).c_str()));
  return words;
}

}  // namespace

LessonSpeech lesson_speech(const LessonSession& lessons, InputKind input) {
  LessonSpeech speech;
  speech.turn = lessons.answer_count();
  const Lesson* lesson = lessons.open_lesson();
  if (!lesson) {
    // The welcome, over the simulation; a lesson opened from the menu is read before it.
    if (!lessons.show_welcome) return speech;
    speech.place = "welcome";
    speech.words = tr("Welcome to Swarm Lab. Lessons:");
    for (const Lesson& l : lessons.shipped())
      add(speech.words, std::string(tr(l.title.c_str())) + ".");
    add(speech.words, tr("Or just the simulation."));
    return speech;
  }
  if (lessons.showing_summary()) {
    speech.place = lesson->id + "/summary";
    speech.words =
        printed(tr("%s: summary."), tr(lesson->title.c_str())) + " " + lessons.finished_line();
    return speech;
  }
  speech.place = lesson->id + "/" + std::to_string(lessons.step());
  if (lessons.marking())
    speech.words = plain(lessons.marking()->feedback, input);
  else
    speech.words = step_words(lessons, input);
  return speech;
}

}  // namespace swarmlab
