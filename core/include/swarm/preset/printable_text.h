#pragma once
/// Text from a preset made safe to echo in a one-line message, on a terminal or in the page.

#include <cstddef>
#include <string>
#include <string_view>

namespace swarm {

/// `text` with every control character escaped (C0 and DEL as \n, \t or \u001b; the C1
/// controls U+0080..U+009F as \u0080..), every byte that is not UTF-8 as \xNN, and cut after
/// about max_bytes of output with "..." appended, so a terminal never obeys an escape sequence
/// hidden in a name and a 100 MB value never reaches a message whole.
std::string printable(std::string_view text, std::size_t max_bytes = 60);

}  // namespace swarm
