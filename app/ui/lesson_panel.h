#pragma once
// The lesson window (the open lesson's step, its task, feedback, back and next) and the
// welcome window (what is on the screen, three things to try, the lessons).

#include "app_state.h"

namespace swarmlab {

/// The lesson window, over the 3D view, when a lesson is open. Its ImGui name is "Lesson".
void draw_lesson_window(AppState& state);
/// The welcome window, on the first start and from Help. Its ImGui name is "Welcome".
void draw_welcome_window(AppState& state);
/// The Lessons menu of the menu bar: every shipped lesson, and the welcome.
void draw_lessons_menu(AppState& state);
/// Lesson text: paragraphs split by a blank line, *emphasis* in the accent colour, wrapped
/// to the window.
void draw_prose(const std::string& text);

}  // namespace swarmlab
