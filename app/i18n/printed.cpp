#include "i18n/printed.h"

#include <cstdio>

namespace swarmlab {

std::string vprinted(const char* format, std::va_list args) {
  std::va_list again;
  va_copy(again, args);
  const int n = std::vsnprintf(nullptr, 0, format, args);
  std::string text(std::size_t(n > 0 ? n : 0) + 1, '\0');
  std::vsnprintf(text.data(), text.size(), format, again);
  va_end(again);
  text.pop_back();
  return text;
}

std::string printed(const char* format, ...) {
  std::va_list args;
  va_start(args, format);
  std::string text = vprinted(format, args);
  va_end(args);
  return text;
}

}  // namespace swarmlab
