#pragma once
/// The tables of assets/i18n/, built into the program (embed_tables.cmake).

#include <string_view>

namespace swarmlab {

/// The JSON text of assets/i18n/languages.json: the languages the app speaks (language_table.h).
std::string_view embedded_language_table();

/// The JSON text of the string table for a language code, or empty when none ships (the
/// language of the texts, the pseudo-language, an unknown code).
std::string_view embedded_table(std::string_view code);

}  // namespace swarmlab
