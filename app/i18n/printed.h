#pragma once
/// A printf format filled into a std::string: the way a translated sentence gets its values, so
/// that a translator may move the words around them ("t = %s reached" -> "已到达 %s").

#include <cstdarg>
#include <string>

namespace swarmlab {

std::string printed(const char* format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;
std::string vprinted(const char* format, std::va_list args);

}  // namespace swarmlab
