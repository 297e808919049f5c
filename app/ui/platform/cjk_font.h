#pragma once
// The Chinese glyphs: a subset of Noto Sans CJK SC holding the characters the Chinese table
// uses, made at build time (docs/i18n.md). Built into the desktop binary
// (cjk_font_embedded.cpp); fetched by the page only when Chinese is chosen (cjk_font_web.cpp),
// so no other language downloads it. Whichever way they come, the bytes reach the font atlas
// only through fonts.cpp, which checks them (font_file_check.h) and hands back what the atlas
// refuses (refuse_cjk_font).

#include <string_view>

namespace swarmlab {

/// The font's bytes; empty while they are not here (the page is still fetching them, or every
/// try failed).
std::string_view cjk_font();
/// Asks for the bytes if they are not here, not on their way and not given up on.
void request_cjk_font();

enum class CjkFontNews {
  none,
  arrived,   ///< new bytes are here: the font atlas must be built again
  given_up,  ///< every try failed (the page was told, with a retry): Chinese cannot be drawn
};
/// What happened since the last call (once each).
CjkFontNews cjk_font_news();
/// True from a failure that gave up until bytes the atlas took arrive: the UI is drawn in
/// English meanwhile, rather than a '?' for every Chinese character.
bool cjk_font_missing();
/// The bytes cjk_font() gave were refused (`why`: the check's words, or the atlas builder's):
/// they are dropped, and this counts as a failed try.
void refuse_cjk_font(std::string_view why);
/// Tries again after giving up (a new choice of Chinese; the page's retry button does the same).
void retry_cjk_font();

}  // namespace swarmlab
