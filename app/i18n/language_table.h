#pragma once
/// Reads assets/i18n/languages.json, the one table of the languages the app speaks: each row's
/// code, native name, decimal separator, locale aliases, whether it is the pseudo-language, and
/// the font it needs (docs/i18n.md). scripts/i18n.py reads the same file for the page.

#include <string>
#include <string_view>
#include <vector>

#include "i18n/language.h"

namespace swarmlab {

/// The table's rows, in order. On failure, empty, and `error` names the row and the field and
/// says the rule ("[5].decimal_separator: must be \".\" or \",\"").
std::vector<Language> read_language_table(std::string_view json, std::string& error);

}  // namespace swarmlab
