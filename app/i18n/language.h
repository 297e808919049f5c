#pragma once
/// The languages the app speaks, and which of them fits a reader's locale: the rows of
/// assets/i18n/languages.json (docs/i18n.md), built into the program.

#include <string>
#include <string_view>
#include <vector>

namespace swarmlab {

struct Language {
  std::string code;                  ///< BCP 47, the name of its table: assets/i18n/<code>.json
  std::string native_name;           ///< as its readers write it, for View > Language
  char decimal_separator = '.';      ///< '.' or ','
  std::vector<std::string> aliases;  ///< the primary subtags of the locales it is chosen for
  bool pseudo = false;               ///< made-up longer texts for layout tests, never offered
  bool needs_cjk_font = false;       ///< its glyphs are beyond DejaVu Sans: Noto Sans CJK SC is loaded
};

/// The languages of the View > Language menu in the table's order; the first is the one the
/// texts are written in (English), whose texts are the tables' keys.
const std::vector<Language>& languages();

/// The language the texts are written in: languages().front().
const Language& source_language();

/// The pseudo-language for layout tests only (#lang= and its code): every text longer, with accents.
const Language& pseudo_language();

/// The language with this exact code (a listed one or the pseudo-language), or null.
const Language* find_language(std::string_view code);

/// The code of the listed language that fits a locale or language tag: the one whose aliases
/// hold its primary subtag (the part before any '_', '-', '.' or '@', compared without regard to
/// case: Portugal's Portuguese gets Brazil's, a Traditional Chinese locale Simplified Chinese).
/// The source language's when none fits (including "C" and "").
std::string language_for_locale(std::string_view locale);

/// The listed languages' codes for a message or a help text, "en, es, ...": each inside
/// `quote`, the source language left out when `translations_only`.
std::string language_codes(std::string_view quote = "", bool translations_only = false);

}  // namespace swarmlab
