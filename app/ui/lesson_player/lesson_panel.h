#pragma once
// The lesson panel (the open lesson's step, its task, feedback, back and next) and the
// welcome window (what is on the screen, three things to try, the lessons).

#include "ui/state/app_state.h"

namespace swarmlab {

/// The open lesson's step, its task, feedback, back and next, with the step's text in a box
/// step_height tall: at the top of the Controls panel in the wide layout and as the drawer's
/// first tab in the compact ones, so that it never covers the swarm. Nothing without a lesson.
void draw_lesson(AppState& state, float step_height);
/// The welcome window, on the first start and from Help. Its ImGui name is tr_id("Welcome"):
/// "Welcome" in the language in use, with "###Welcome" as its ID.
void draw_welcome_window(AppState& state);
/// The Lessons menu of the menu bar: every shipped lesson, the welcome, and the progress as a
/// file (Download progress; Load progress... in the browser).
void draw_lessons_menu(AppState& state);
/// When progress is not kept as usual (progress_record.h): once, the notice in the status line
/// and a window that says so, with Download progress, Load progress... (in the browser) and
/// Close. (The live region says it once: the announcer's Situation::notice.)
void draw_progress_notice(AppState& state);
/// Where the open lesson's step hides `what` (lesson.h, LessonHidden) until its question is
/// answered: draws one line saying so in its place and returns true; false (nothing drawn)
/// when it is shown. The read-outs, the particle card and the plots call it first.
bool draw_hidden_by_lesson(const AppState& state, LessonHidden what);
/// Lesson text: paragraphs split by a blank line, *emphasis* in the accent colour, wrapped
/// to the window.
void draw_prose(const AppState& state, const std::string& text);

}  // namespace swarmlab
