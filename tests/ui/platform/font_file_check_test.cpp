#include "ui/platform/font_file_check.h"

#include <doctest/doctest.h>

#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

using namespace swarmlab;

namespace {

std::string dejavu_sans() {
  std::ifstream in(SWARM_FONT_DIR "/DejaVuSans.ttf", std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void put16(std::string& b, std::size_t at, std::uint32_t v) {
  b[at] = char(v >> 8);
  b[at + 1] = char(v);
}
void put32(std::string& b, std::size_t at, std::uint32_t v) {
  put16(b, at, v >> 16);
  put16(b, at + 2, v & 0xFFFF);
}

struct TableSpec {
  std::string tag;
  std::uint32_t length;
};

/// A font of these tables, zero-filled, laid out after the directory as a font tool lays them
/// out, with one cmap encoding (pointing to its byte 12) and one long horizontal metric.
std::string font_of(std::string magic, const std::vector<TableSpec>& tables) {
  std::string b(12 + 16 * tables.size(), '\0');
  b.replace(0, 4, magic);
  put16(b, 4, std::uint32_t(tables.size()));
  for (std::size_t i = 0; i < tables.size(); ++i) {
    const std::size_t entry = 12 + 16 * i, offset = b.size();
    b.replace(entry, 4, tables[i].tag);
    put32(b, entry + 8, std::uint32_t(offset));
    put32(b, entry + 12, tables[i].length);
    b.append(tables[i].length, '\0');
    if (tables[i].tag == "cmap") {
      put16(b, offset + 2, 1);
      put32(b, offset + 4 + 4, 12);
    }
    if (tables[i].tag == "hhea") put16(b, offset + 34, 1);
  }
  return b;
}

const std::vector<TableSpec> kOpenType = {{"CFF ", 64}, {"cmap", 20}, {"head", 54},
                                          {"hhea", 36}, {"hmtx", 4},  {"maxp", 6}};
const std::vector<TableSpec> kTrueType = {{"cmap", 20}, {"glyf", 8}, {"head", 54},
                                          {"hhea", 36}, {"hmtx", 4}, {"loca", 4}};

/// Where table `tag`'s directory entry starts in a font_of() font.
std::size_t entry_of(const std::string& font, const std::string& tag) {
  for (std::size_t at = 12; at + 16 <= font.size(); at += 16)
    if (font.compare(at, 4, tag) == 0) return at;
  FAIL("no table " << tag);
  return 0;
}

}  // namespace

TEST_CASE("font_file_check: a whole font is taken, TrueType and OpenType") {
  const std::string dejavu = dejavu_sans();
  REQUIRE(dejavu.size() == 759720);
  CHECK(font_file_problem(dejavu) == "");
  CHECK(font_file_problem(font_of("OTTO", kOpenType)) == "");
  CHECK(font_file_problem(font_of("true", kTrueType)) == "");
}

TEST_CASE("font_file_check: a font cut short is refused wherever it was cut") {
  const std::string dejavu = dejavu_sans();
  // The first 4,096 bytes (what crashed the page), and cuts down to the header.
  for (std::size_t kept : {std::size_t(4096), dejavu.size() - 1, dejavu.size() / 2,
                           std::size_t(12 + 16 * 20), std::size_t(100), std::size_t(12)}) {
    CAPTURE(kept);
    const std::string problem = font_file_problem(std::string_view(dejavu).substr(0, kept));
    CHECK(problem != "");
  }
  CHECK(font_file_problem(std::string_view(dejavu).substr(0, 4096)) ==
        "the font's table 'GPOS' (bytes 1020 to 41606) lies outside the file's 332 to 4096 (the "
        "file may be cut short)");
  CHECK(font_file_problem(std::string_view(dejavu).substr(0, 100)) ==
        "the font's table directory (332 bytes) is longer than the file (100)");
}

TEST_CASE("font_file_check: what is not a font is refused by its first bytes or its size") {
  CHECK(font_file_problem("") == "the font file has 0 bytes, fewer than a font's header (12)");
  CHECK(font_file_problem("<!DOCTYPE html><html><head><title>Sign in to the school network"
                          "</title></head><body></body></html>") ==
        "the file is not an OpenType or TrueType font (it starts with neither 'OTTO', 0x00010000 "
        "nor 'true')");
  std::string collection = font_of("OTTO", kOpenType);
  collection.replace(0, 4, "ttcf");
  CHECK(font_file_problem(collection) == "the font file is a font collection, not a single font");
  std::string oversize = dejavu_sans();
  oversize.resize(kMaxFontFileBytes + 1);
  CHECK(font_file_problem(oversize) ==
        "the font file has 4194305 bytes, more than the limit of 4194304");
  oversize.resize(kMaxFontFileBytes);
  CHECK(font_file_problem(oversize) == "");  // the limit itself is taken
}

TEST_CASE("font_file_check: a table directory that lies is refused") {
  std::string font = font_of("OTTO", kOpenType);
  SUBCASE("no tables, or more than the limit") {
    put16(font, 4, 0);
    CHECK(font_file_problem(font) == "the font lists 0 tables, not 1 to 64");
    put16(font, 4, 65535);
    CHECK(font_file_problem(font) == "the font lists 65535 tables, not 1 to 64");
  }
  SUBCASE("a table whose end wraps past 2^32") {
    put32(font, entry_of(font, "head") + 8, 0xFFFFFFF0u);
    put32(font, entry_of(font, "head") + 12, 0x20);
    CHECK(font_file_problem(font).find("'head' (bytes 4294967280 to 4294967312) lies outside") !=
          std::string::npos);
  }
  SUBCASE("a table inside the header") {
    put32(font, entry_of(font, "cmap") + 8, 0);
    CHECK(font_file_problem(font).find("'cmap' (bytes 0 to 20) lies outside") != std::string::npos);
  }
  SUBCASE("a table stb_truetype needs is missing or too short") {
    font.replace(entry_of(font, "cmap"), 4, "cmaq");
    CHECK(font_file_problem(font) == "the font has no table 'cmap'");
    std::string short_head = font_of("OTTO", kOpenType);
    put32(short_head, entry_of(short_head, "head") + 12, 53);
    CHECK(font_file_problem(short_head) == "the font's table 'head' has 53 bytes, fewer than 54");
    std::vector<TableSpec> no_loca = kTrueType;
    no_loca.pop_back();
    CHECK(font_file_problem(font_of("true", no_loca)) ==
          "the font has neither outlines in 'CFF ' nor in 'glyf' with 'loca'");
  }
  SUBCASE("cmap or hmtx pointing past their tables") {
    const std::size_t cmap = 12 + 16 * kOpenType.size() + 64;  // after CFF's 64 bytes
    put16(font, cmap + 2, 3);                                  // three records in 20 bytes
    CHECK(font_file_problem(font) ==
          "the font's 'cmap' lists 3 encodings, more than its bytes hold");
    put16(font, cmap + 2, 1);
    put32(font, cmap + 8, 17);
    CHECK(font_file_problem(font) == "the font's 'cmap' points to byte 17, past its end");
    put32(font, cmap + 8, 12);
    const std::size_t hhea = cmap + 20 + 54;
    put16(font, hhea + 34, 2);  // two long metrics in hmtx's 4 bytes
    CHECK(font_file_problem(font) ==
          "the font's 'hmtx' is shorter than the 2 metrics 'hhea' announces");
  }
}
