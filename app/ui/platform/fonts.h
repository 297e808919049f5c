#pragma once
// The UI font (DejaVu Sans, compiled into the binary) and the UI scale for projectors.

#include "access/theme_palette.h"

namespace swarmlab {

/// Rebuilds ImGui's font atlas and style for a UI scale (1 = 16 px text) in a theme, with the
/// glyphs of the language in use (translator()). Call between frames; the renderer's font
/// texture must be recreated afterwards.
void apply_ui_scale(float scale, Theme theme);

}  // namespace swarmlab
