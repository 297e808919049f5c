#pragma once
// The themes applied to Dear ImGui: the palette (access/theme_palette.h) mapped onto the
// style's colours, with the sizes scaled for the UI scale.

#include <imgui.h>

#include "access/theme_palette.h"

namespace swarmlab {

/// Rebuilds ImGui's style for this scale in the current theme (fonts.cpp, on a new UI scale).
void apply_style(float scale);
/// Switches the theme, keeping the scale last applied. Between frames.
void use_theme(Theme theme);
Theme current_theme();
/// The current theme's colours, for what the panels draw themselves (plots, the 3D view).
const Palette& current_palette();

inline ImVec4 colour_vec4(Colour c) {
  return ImVec4(c.r / 255.0f, c.g / 255.0f, c.b / 255.0f, c.a / 255.0f);
}

}  // namespace swarmlab
