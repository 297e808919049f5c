#include "lessons/device_words.h"

#include <algorithm>
#include <vector>

namespace swarmlab {
namespace {

constexpr const char* kRule =
    "a device choice is {touch words|mouse words} or {touch|mouse|keyboard words}: 2 or 3 "
    "non-empty alternatives split by '|', closed on the same line";

/// The alternatives of the choice starting at text[open] ('{') and where it closes, or an
/// empty list when it breaks the rule.
std::vector<std::string_view> alternatives(std::string_view text, std::size_t open,
                                           std::size_t* close) {
  std::vector<std::string_view> out;
  std::size_t start = open + 1;
  for (std::size_t i = open + 1; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '{' || c == '\n') return {};
    if (c == '|' || c == '}') {
      if (i == start) return {};
      out.push_back(text.substr(start, i - start));
      start = i + 1;
      if (c == '}') {
        *close = i;
        return out.size() == 2 || out.size() == 3 ? out : std::vector<std::string_view>{};
      }
    }
  }
  return {};
}

}  // namespace

std::string device_words(std::string_view text, InputKind input) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    std::size_t close = 0;
    const std::vector<std::string_view> choice =
        text[i] == '{' ? alternatives(text, i, &close) : std::vector<std::string_view>{};
    if (choice.empty()) {
      out += text[i];
      continue;
    }
    const std::size_t pick = input == InputKind::touch   ? 0
                             : input == InputKind::mouse ? 1
                                                         : choice.size() - 1;
    out += choice[pick];
    i = close;
  }
  return out;
}

std::string device_words_problem(std::string_view text) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '}') return std::string("a '}' with no '{' before it (") + kRule + ")";
    if (text[i] != '{') continue;
    std::size_t close = 0;
    const std::vector<std::string_view> choice = alternatives(text, i, &close);
    if (choice.empty()) return kRule;
    // Each alternative is shown alone, so each closes its own *emphasis*.
    for (std::string_view words : choice)
      if (std::count(words.begin(), words.end(), '*') % 2 != 0)
        return "an emphasis is not closed inside one alternative of a device choice (write "
               "{tap *Play*|click *Play*})";
    i = close;
  }
  return {};
}

}  // namespace swarmlab
