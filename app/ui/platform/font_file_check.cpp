#include "ui/platform/font_file_check.h"

#include <cstdint>
#include <string>

namespace swarmlab {
namespace {

// OpenType's numbers are big-endian; every read below is inside the bytes (checked first).
std::uint32_t u16(std::string_view b, std::size_t at) {
  return std::uint32_t(std::uint8_t(b[at])) << 8 | std::uint8_t(b[at + 1]);
}
std::uint32_t u32(std::string_view b, std::size_t at) { return u16(b, at) << 16 | u16(b, at + 2); }

struct Table {
  std::uint32_t offset = 0, length = 0;
  bool found = false;
};

std::string quoted(std::string_view tag) { return "'" + std::string(tag) + "'"; }

}  // namespace

std::string font_file_problem(std::string_view bytes) {
  const std::size_t size = bytes.size();
  if (size < 12)
    return "the font file has " + std::to_string(size) + " bytes, fewer than a font's header (12)";
  if (size > kMaxFontFileBytes)
    return "the font file has " + std::to_string(size) + " bytes, more than the limit of " +
           std::to_string(kMaxFontFileBytes);
  const std::string_view magic = bytes.substr(0, 4);
  if (magic == "ttcf") return "the font file is a font collection, not a single font";
  if (magic != "OTTO" && magic != std::string_view("\0\1\0\0", 4) && magic != "true")
    return "the file is not an OpenType or TrueType font (it starts with neither 'OTTO', "
           "0x00010000 nor 'true')";

  const int tables = int(u16(bytes, 4));
  if (tables < 1 || tables > kMaxFontTables)
    return "the font lists " + std::to_string(tables) + " tables, not 1 to " +
           std::to_string(kMaxFontTables);
  const std::size_t directory_end = 12 + 16 * std::size_t(tables);
  if (directory_end > size)
    return "the font's table directory (" + std::to_string(directory_end) +
           " bytes) is longer than the file (" + std::to_string(size) + ")";

  // The tables stb_truetype reads, and the bytes of each that it reads at fixed places.
  Table cmap, head, hhea, hmtx, maxp, loca, glyf, cff;
  const struct {
    std::string_view tag;
    Table* table;
    std::uint32_t least;  // bytes
  } needs[] = {{"cmap", &cmap, 4}, {"head", &head, 54}, {"hhea", &hhea, 36}, {"hmtx", &hmtx, 0},
               {"maxp", &maxp, 6}, {"loca", &loca, 0},  {"glyf", &glyf, 0},  {"CFF ", &cff, 4}};
  for (int i = 0; i < tables; ++i) {
    const std::size_t entry = 12 + 16 * std::size_t(i);
    const std::string_view tag = bytes.substr(entry, 4);
    const std::uint32_t offset = u32(bytes, entry + 8), length = u32(bytes, entry + 12);
    if (offset < directory_end || std::uint64_t(offset) + length > size)
      return "the font's table " + quoted(tag) + " (bytes " + std::to_string(offset) + " to " +
             std::to_string(std::uint64_t(offset) + length) + ") lies outside the file's " +
             std::to_string(directory_end) + " to " + std::to_string(size) +
             " (the file may be cut short)";
    for (const auto& need : needs) {
      if (tag != need.tag || need.table->found) continue;  // stb_truetype takes the first
      if (length < need.least)
        return "the font's table " + quoted(tag) + " has " + std::to_string(length) +
               " bytes, fewer than " + std::to_string(need.least);
      *need.table = {offset, length, true};
    }
  }
  for (const auto& [tag, table] :
       {std::pair{"cmap", &cmap}, {"head", &head}, {"hhea", &hhea}, {"hmtx", &hmtx}})
    if (!table->found) return "the font has no table " + quoted(tag);
  if (!cff.found && !(glyf.found && loca.found))
    return "the font has neither outlines in 'CFF ' nor in 'glyf' with 'loca'";

  // Where stb_truetype goes from these tables without looking: cmap's encoding records and the
  // subtables they point to, and the long horizontal metrics.
  const std::uint32_t encodings = u16(bytes, cmap.offset + 2);
  if (4 + 8 * std::uint64_t(encodings) > cmap.length)
    return "the font's 'cmap' lists " + std::to_string(encodings) +
           " encodings, more than its bytes hold";
  for (std::uint32_t e = 0; e < encodings; ++e) {
    const std::uint32_t subtable = u32(bytes, cmap.offset + 4 + 8 * e + 4);
    if (std::uint64_t(subtable) + 4 > cmap.length)
      return "the font's 'cmap' points to byte " + std::to_string(subtable) + ", past its end";
  }
  const std::uint32_t metrics = u16(bytes, hhea.offset + 34);
  if (4 * std::uint64_t(metrics) > hmtx.length)
    return "the font's 'hmtx' is shorter than the " + std::to_string(metrics) +
           " metrics 'hhea' announces";
  return "";
}

}  // namespace swarmlab
