#pragma once
// The themes applied to Dear ImGui: the palette (access/theme_palette.h) mapped onto the
// style's colours, with the sizes scaled for the UI scale. The theme in use is the app's
// (AppState::presentation.theme): what the panels draw themselves takes its colours from
// palette(state.presentation.theme), and nothing here remembers a theme or a scale.

#include <imgui.h>

#include "access/theme_palette.h"

namespace swarmlab {

/// Rebuilds ImGui's style for this scale in this theme: on a new UI scale (fonts.cpp) and on a
/// new theme (classroom_outputs.cpp). Between frames.
void apply_style(float scale, Theme theme);

inline ImVec4 colour_vec4(Colour c) {
  return ImVec4(c.r / 255.0f, c.g / 255.0f, c.b / 255.0f, c.a / 255.0f);
}

}  // namespace swarmlab
