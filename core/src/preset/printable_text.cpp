#include "swarm/preset/printable_text.h"

#include <cstdio>

namespace swarm {
namespace {

std::string escaped(unsigned code, const char* form) {
  char buf[12];
  std::snprintf(buf, sizeof buf, form, code);
  return buf;
}

/// Length of the UTF-8 sequence starting at text[i], or 0 if it is not one.
std::size_t utf8_length(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return (unsigned char)text[k]; };
  const unsigned lead = byte(i);
  const std::size_t n = lead >= 0xF0 && lead <= 0xF4 ? 4 : lead >= 0xE0 ? 3 : lead >= 0xC2 ? 2 : 0;
  if (n == 0 || i + n > text.size()) return 0;
  for (std::size_t k = 1; k < n; ++k)
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
  return n;
}

}  // namespace

std::string printable(std::string_view text, std::size_t max_bytes) {
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    if (out.size() >= max_bytes) return out + "...";
    const unsigned char c = (unsigned char)text[i];
    if (c == '\n') {
      out += "\\n", ++i;
    } else if (c == '\t') {
      out += "\\t", ++i;
    } else if (c < 0x20 || c == 0x7F) {
      out += escaped(c, "\\u%04x"), ++i;
    } else if (c < 0x80) {
      out += char(c), ++i;
    } else if (const std::size_t n = utf8_length(text, i); n == 0) {
      out += escaped(c, "\\x%02x"), ++i;
    } else if (c == 0xC2 && (unsigned char)text[i + 1] < 0xA0) {
      out += escaped((unsigned char)text[i + 1], "\\u%04x"), i += 2;  // a C1 control
    } else {
      out.append(text.substr(i, n)), i += n;
    }
  }
  return out;
}

}  // namespace swarm
