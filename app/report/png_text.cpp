#include "report/png_text.h"

#include <array>
#include <cstdint>

namespace swarmlab::report {
namespace {

constexpr std::size_t kSignature = 8;         // the PNG signature's bytes
constexpr std::size_t kIhdrChunk = 4 + 4 + 13 + 4;  // length, type, IHDR's data, CRC

/// The CRC-32 of PNG chunks (ISO 3309, polynomial 0xEDB88320, reflected).
std::uint32_t crc32(const std::string& bytes) {
  static const std::array<std::uint32_t, 256> table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t n = 0; n < 256; ++n) {
      std::uint32_t c = n;
      for (int k = 0; k < 8; ++k) c = c & 1 ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[n] = c;
    }
    return t;
  }();
  std::uint32_t c = 0xFFFFFFFFu;
  for (unsigned char b : bytes) c = table[(c ^ b) & 0xFF] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

std::string big_endian(std::uint32_t x) {
  return {char(x >> 24), char((x >> 16) & 0xFF), char((x >> 8) & 0xFF), char(x & 0xFF)};
}

/// keyword, NUL, compression flag and method (0: none), no language tag, no translated
/// keyword, the UTF-8 text.
std::string itxt_chunk(const std::string& keyword, const std::string& text) {
  const std::string type_and_data = "iTXt" + keyword + std::string(1, '\0') + std::string(2, '\0') +
                                    std::string(1, '\0') + std::string(1, '\0') + text;
  return big_endian(std::uint32_t(type_and_data.size() - 4)) + type_and_data +
         big_endian(crc32(type_and_data));
}

}  // namespace

std::string png_with_text(const std::string& png,
                          const std::vector<std::pair<std::string, std::string>>& entries) {
  static const std::string signature = "\x89PNG\r\n\x1a\n";
  if (png.size() < kSignature + kIhdrChunk || png.compare(0, kSignature, signature) != 0 ||
      png.compare(kSignature, 8, big_endian(13) + "IHDR") != 0)
    return png;
  std::string chunks;
  for (const auto& [keyword, text] : entries) chunks += itxt_chunk(keyword, text);
  return png.substr(0, kSignature + kIhdrChunk) + chunks + png.substr(kSignature + kIhdrChunk);
}

std::vector<std::pair<std::string, std::string>> png_text_of(const std::vector<std::string>& lines) {
  if (lines.empty()) return {};
  std::string all;
  for (const std::string& line : lines) all += (all.empty() ? "" : "\n") + line;
  return {{"Software", lines.front()}, {"Comment", all}};
}

}  // namespace swarmlab::report
