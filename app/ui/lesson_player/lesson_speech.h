#pragma once
// What a lesson says to a listener (the page's live region, through the announcer): the welcome
// when it opens, a step with its question and options when it is shown, the feedback on each
// answer, the summary at the end. Plain sentences: no *emphasis* marks, device words for the
// student's input.

#include <cstddef>
#include <string>

#include "lessons/device_words.h"

namespace swarmlab {

class LessonSession;

/// The words, and a turn that changes with every answer, so that the same feedback given to a
/// second try is said again.
struct LessonSpeech {
  std::string words;  ///< "" when no lesson and no welcome is shown
  std::size_t turn = 0;
};

LessonSpeech lesson_speech(const LessonSession& lessons, InputKind input);

}  // namespace swarmlab
