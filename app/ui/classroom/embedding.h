#pragma once
// Inside a course page (Moodle, Canvas, a teacher's site): the page's ?embed or #embed
// (web/embed_bridge.js) shows the app without what a page section does not want: the menu bar
// (and with it Quit, the Lessons and View menus; a course page opens lessons and presets
// through the postMessage bridge or a link) and the welcome window. The run, the panels, the
// lesson panel and the parallel DOM stay as they are.

#include "ui/state/app_state.h"

namespace swarmlab {

/// On: hides the menu bar and the welcome; off: the app as a page of its own again.
void set_embedded(AppState& state, bool on);

}  // namespace swarmlab
