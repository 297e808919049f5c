#pragma once
// The windows the panels are drawn in, placed on the screen layout's rectangles
// (classroom/screen_layout.h) once a frame by App: the menu bar, the side panels or the
// compact layout's drawer, and the strips above and below the 3D view. Each window is recorded
// in AppState::layout.panels for swarmlab.state().

#include <cstddef>
#include <utility>

#include "ui/input/touch_gestures.h"
#include "ui/state/app_state.h"

namespace swarmlab {

/// The main menu bar (Scenario, View, Lessons, Help and the title); returns its height.
float draw_menu_bar(AppState& state);

/// The lesson step the drawer showed last: a new one brings the Lesson tab to the front.
using LessonTabStep = std::pair<const Lesson*, std::size_t>;

/// The Controls and Plots windows (wide), or one drawer beside or under the view with them as
/// tabs (compact). A finger dragging on a window scrolls it.
void draw_panel_windows(AppState& state, const ScreenLayout& layout, const TouchFrame& touch,
                        LessonTabStep* lesson_tab_step);

/// Around the 3D view, never over it: the transport bar above, the read-outs below. Their
/// heights are measured for the next frame's layout.
void draw_view_strips(AppState& state, const ScreenLayout& layout);

}  // namespace swarmlab
