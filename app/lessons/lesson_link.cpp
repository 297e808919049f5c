#include "lessons/lesson_link.h"

#include <cstdint>

namespace swarmlab {
namespace {

constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_";

int sextet(char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '-' || c == '+') return 62;
  if (c == '_' || c == '/') return 63;
  return -1;
}

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

}  // namespace

std::string to_base64url(std::string_view bytes) {
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::uint32_t bits = 0;
  int count = 0;
  for (unsigned char c : bytes) {
    bits = (bits << 8) | c;
    count += 8;
    while (count >= 6) {
      count -= 6;
      out += kAlphabet[(bits >> count) & 63];
    }
  }
  if (count > 0) out += kAlphabet[(bits << (6 - count)) & 63];
  return out;
}

bool from_base64url(std::string_view text, std::string* bytes) {
  std::string sextets;
  bool padding = false;
  for (char c : text) {
    if (is_space(c)) continue;
    if (c == '=') {
      padding = true;
      continue;
    }
    if (padding || sextet(c) < 0) return false;  // nothing may follow the padding
    sextets += c;
  }
  if (sextets.empty() || sextets.size() % 4 == 1) return false;
  bytes->clear();
  std::uint32_t bits = 0;
  int count = 0;
  for (char c : sextets) {
    bits = (bits << 6) | std::uint32_t(sextet(c));
    count += 6;
    if (count >= 8) {
      count -= 8;
      *bytes += char((bits >> count) & 0xff);
    }
  }
  return true;
}

std::string lesson_link_fragment(const std::string& shipped_id, const std::string& json) {
  return "#lesson=" + (shipped_id.empty() ? to_base64url(json) : shipped_id);
}

LessonLinkTarget read_lesson_link(std::string_view value,
                                  const std::vector<std::string>& shipped_ids) {
  LessonLinkTarget out;
  while (!value.empty() && is_space(value.front())) value.remove_prefix(1);
  while (!value.empty() && is_space(value.back())) value.remove_suffix(1);
  for (const std::string& id : shipped_ids)
    if (value == id) {
      out.id = id;
      return out;
    }
  std::string text;
  std::size_t first = 0;
  if (from_base64url(value, &text)) {
    first = text.find_first_not_of(" \t\r\n");
    if (first != std::string::npos && text[first] == '{') {
      out.json = std::move(text);
      return out;
    }
  }
  std::string names;
  for (const std::string& id : shipped_ids) names += (names.empty() ? "" : ", ") + id;
  out.error = "the text after #lesson= is neither a shipped lesson's id (" +
              (names.empty() ? std::string("none is shipped") : names) +
              ") nor a lesson written by Share (its JSON in base64url); the link may have been "
              "cut short";
  return out;
}

}  // namespace swarmlab
