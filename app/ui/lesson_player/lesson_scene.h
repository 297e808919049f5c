#pragma once
// A lesson step carried out on the app: the session (lesson_session.h) says what a step
// shows, this opens its preset and sets its plot, selection and overlay.

#include <cstddef>
#include <string>

#include "ui/state/app_state.h"

namespace swarmlab {

/// Moves the app to what a lesson step shows: opens the scene's preset when it changes, then
/// sets the plot tab, the selection and the spring overlay, and pauses for a prediction.
void show_lesson_scene(AppState& app, const LessonScene& scene);

/// Opens a lesson (a shipped one, or JSON text, or an id) and moves the app to it. The
/// text and id forms return "" or the message, the running lesson staying.
void open_lesson(AppState& app, const Lesson& lesson);
std::string open_lesson_json(AppState& app, const std::string& json);
std::string open_lesson_id(AppState& app, const std::string& id);

/// Opens what a file holds (opened by path, picked or dropped): a lesson file (looks_like_lesson)
/// as a lesson, anything else as a preset named `location`. Returns "" or the message, the
/// lesson's or the preset's, the running lesson and preset staying.
std::string open_file_text(AppState& app, const std::string& text, const std::string& location);

/// Marks a picked option; a prediction plays the run.
Marking answer_lesson_option(AppState& app, std::size_t option);

/// Called each frame after the run advanced while playing: a step that sets how long its run
/// lasts keeps it going, so that it never ends while the student reads. "loop" starts a run
/// that has ended again from its first moment; "until" continues a run that ended before
/// that time up to it.
void keep_lesson_run_going(AppState& app);

}  // namespace swarmlab
