#pragma once
// What a lesson says to a listener (the page's live region, through the announcer): the welcome
// when it opens, a step with its question and options when it is shown (with the prediction
// and the outcome to compare once it is made), the feedback on each answer, the summary at the
// end. Plain sentences: no *emphasis* marks, device words for the student's input.

#include <cstddef>
#include <string>

#include "lessons/device_words.h"

namespace swarmlab {

class LessonSession;

/// The words, where the lesson is and how many answers were given: the words are said when the
/// place or the turn changes, not when only the device words do (a student who tabs, then
/// clicks, does not hear the step again), and the same feedback to a second try is said again.
struct LessonSpeech {
  std::string words;  ///< "" when no lesson and no welcome is shown
  std::string place;  ///< "welcome", "<lesson id>/<step>" or "<lesson id>/summary"
  std::size_t turn = 0;
};

LessonSpeech lesson_speech(const LessonSession& lessons, InputKind input);

}  // namespace swarmlab
