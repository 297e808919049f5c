#pragma once
// The line work of the 3D view, drawn with ImDrawList over the particles: the container as a
// translucent wire sphere, the centre of mass, trails, the orbit ahead of the selected
// particle, the springs of the paper's Fig. 1, the axes and the colour legend. ImGui's
// anti-aliased thick lines work the same in OpenGL 3.3 and WebGL2 (GL line widths do not).

#include "ui/state/app_state.h"

namespace swarmlab {

/// Draws the overlay for the current frame; the camera must be updated for state.layout.view.
void draw_scene_overlay(AppState& state);

}  // namespace swarmlab
