#include "ui/classroom/embedding.h"

namespace swarmlab {

void set_embedded(AppState& state, bool on) {
  if (state.embedded == on) return;
  state.embedded = on;
  // The welcome speaks of the menus ("Open Scenario...") that an embedded app has not, and
  // would cover the course page's section on a student's first visit.
  if (on) state.lessons.show_welcome = false;
  state.layout.menus.clear();  // state().menus: no menu bar
  state.layout.resize_panels = true;
}

}  // namespace swarmlab
