#pragma once
// The Chinese glyphs: a subset of Noto Sans CJK SC holding the characters the Chinese table
// uses, made at build time (docs/i18n.md). Built into the desktop binary
// (cjk_font_embedded.cpp); fetched by the page only when Chinese is chosen (cjk_font_web.cpp),
// so no other language downloads it.

#include <string_view>

namespace swarmlab {

/// The font's bytes; empty while they are not here (the page is still fetching them, or the
/// fetch failed: Chinese then shows boxes until the next try).
std::string_view cjk_font();
/// Asks for the bytes if they are not here and not on their way.
void request_cjk_font();
/// True once after the requested bytes arrived: the font atlas must be built again.
bool cjk_font_arrived();

}  // namespace swarmlab
