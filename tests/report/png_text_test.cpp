#include "report/png_text.h"

#include <doctest/doctest.h>

using namespace swarmlab::report;

namespace {

// A 1x1 grey PNG and an iTXt chunk "Comment" = "a\nb", both built with Python's zlib and
// struct (zlib.crc32 for the CRCs), independently of the code under test.
const std::string kOnePixel(
    "\x89\x50\x4e\x47\x0d\x0a\x1a\x0a\x00\x00\x00\x0d\x49\x48\x44\x52\x00\x00\x00\x01\x00\x00"
    "\x00\x01\x08\x00\x00\x00\x00\x3a\x7e\x9b\x55\x00\x00\x00\x0a\x49\x44\x41\x54\x78\x9c\x63"
    "\x60\x00\x00\x00\x02\x00\x01\x48\xaf\xa4\x71\x00\x00\x00\x00\x49\x45\x4e\x44\xae\x42\x60"
    "\x82",
    67);
const std::string kCommentChunk(
    "\x00\x00\x00\x0f\x69\x54\x58\x74\x43\x6f\x6d\x6d\x65\x6e\x74\x00\x00\x00\x00\x00\x61\x0a"
    "\x62\xfa\x58\x51\xed",
    27);
constexpr std::size_t kAfterIhdr = 8 + 25;  // the signature and the IHDR chunk

}  // namespace

TEST_CASE("png text: an iTXt chunk goes right after IHDR, with the CRC zlib gives") {
  const std::string png = png_with_text(kOnePixel, {{"Comment", "a\nb"}});
  CHECK(png == kOnePixel.substr(0, kAfterIhdr) + kCommentChunk + kOnePixel.substr(kAfterIhdr));
}

TEST_CASE("png text: what is not a PNG comes back unchanged") {
  CHECK(png_with_text("GIF89a", {{"Comment", "x"}}) == "GIF89a");
  CHECK(png_with_text(kOnePixel.substr(0, 20), {{"Comment", "x"}}) == kOnePixel.substr(0, 20));
  std::string no_ihdr = kOnePixel;
  no_ihdr[12] = 'X';
  CHECK(png_with_text(no_ihdr, {{"Comment", "x"}}) == no_ihdr);
}

TEST_CASE("png text: provenance lines as Software (the first) and Comment (all)") {
  const auto entries = png_text_of({"made by swarmlab abc", "date: d"});
  REQUIRE(entries.size() == 2);
  CHECK(entries[0] == std::pair<std::string, std::string>{"Software", "made by swarmlab abc"});
  CHECK(entries[1] == std::pair<std::string, std::string>{"Comment", "made by swarmlab abc\ndate: d"});
  CHECK(png_text_of({}).empty());
}
