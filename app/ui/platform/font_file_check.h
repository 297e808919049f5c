#pragma once
// A font file's bytes checked before Dear ImGui's atlas builder hands them to stb_truetype,
// which trusts every offset a font holds: a file cut short (a dropped connection) made it read
// past the bytes it was given ("memory access out of bounds" ended the page), and a web page
// served under the font's name (a school's captive portal) left the atlas empty. Pure: no
// ImGui, no files.

#include <cstddef>
#include <string>
#include <string_view>

namespace swarmlab {

/// The largest font file taken (bytes); the Chinese subset is about 150 kB, Noto Sans CJK SC
/// whole about 16 MB.
inline constexpr std::size_t kMaxFontFileBytes = std::size_t(4) << 20;
/// The most tables a font's directory may list (the fonts we ship have 14 and 20).
inline constexpr int kMaxFontTables = 64;

/// Why these bytes are no font stb_truetype may read, in one English sentence, or "" when they
/// are one: a size from the header's 12 bytes to kMaxFontFileBytes; a single OpenType or
/// TrueType font ('OTTO', 0x00010000 or 'true'; a collection is not taken); a table directory
/// of 1 to kMaxFontTables tables, each table lying inside the file; the tables stb_truetype
/// needs (cmap, head, hhea, hmtx, and CFF or glyf with loca) present and long enough for the
/// fixed fields it reads, and cmap's encoding records and horizontal metrics inside their tables.
std::string font_file_problem(std::string_view bytes);

}  // namespace swarmlab
