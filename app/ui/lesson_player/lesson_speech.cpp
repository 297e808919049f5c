#include "ui/lesson_player/lesson_speech.h"

#include "ui/lesson_player/lesson_session.h"

namespace swarmlab {
namespace {

/// The text as it is read: device words chosen, emphasis marks dropped, paragraphs joined.
std::string plain(const std::string& text, InputKind input) {
  std::string out;
  for (const char c : without_emphasis(device_words(text, input))) {
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
  std::string words = lesson.title + ", step " + std::to_string(i + 1) + " of " +
                      std::to_string(lesson.steps.size()) + ".";
  add(words, plain(step.text, input));
  if (!step.task) return words;
  add(words, plain(step.task->prompt, input));
  const bool predict = step.task->kind == LessonTask::Kind::predict;
  if (predict && lessons.prediction()) {
    // Made on an earlier visit: the panel shows it and the outcome, not the options.
    add(words, "Your prediction: " + plain(step.task->options[*lessons.prediction()], input) + ".");
    if (!step.task->outcome.empty()) add(words, "Now compare: " + plain(step.task->outcome, input));
    return words;
  }
  for (std::size_t k = 0; k < step.task->options.size(); ++k)
    add(words, std::string(predict ? "Predict " : "Pick ") + char('A' + k) + ": " +
                   plain(step.task->options[k], input) + ".");
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
    speech.words = "Welcome to Swarm Lab. Lessons:";
    for (const Lesson& l : lessons.shipped()) add(speech.words, l.title + ".");
    add(speech.words, "Or just the simulation.");
    return speech;
  }
  if (lessons.showing_summary()) {
    speech.place = lesson->id + "/summary";
    speech.words = lesson->title + ": summary. " + lessons.finished_line();
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
