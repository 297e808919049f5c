#pragma once
/// Switches the front end's language (translator()) to one the app ships.

#include <string>
#include <string_view>

namespace swarmlab {

/// Speaks the language with this code: a listed one from its embedded table, English, or the
/// pseudo-language. False, with the reason in `error`, for an unknown code or a table that
/// does not read; the language in use then stays.
bool speak(std::string_view code, std::string& error);

}  // namespace swarmlab
