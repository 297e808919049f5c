#pragma once
/// The languages the app speaks, and which of them fits a reader's locale.

#include <string>
#include <string_view>
#include <vector>

namespace swarmlab {

struct Language {
  std::string code;         ///< BCP 47: "en", "es", "de", "fr", "pt-BR", "zh-CN"
  std::string native_name;  ///< as its readers write it: "Español", "中文（简体）"
  char decimal_separator;   ///< '.' or ','
  bool needs_cjk_font;      ///< its glyphs are beyond DejaVu Sans: a Noto CJK subset is loaded
};

/// The languages of the View > Language menu, English first.
const std::vector<Language>& languages();

/// The pseudo-language for layout tests only (#lang=x-pseudo): every text longer, with accents.
const Language& pseudo_language();

/// The language with this exact code (a listed one or the pseudo-language), or null.
const Language* find_language(std::string_view code);

/// The listed language that best fits a locale or language tag: "es-MX" and "es_ES.UTF-8" give
/// "es", "pt" and "pt-PT" give "pt-BR", "zh", "zh-Hans" and "zh-SG" give "zh-CN"; matching
/// ignores case. English when none fits (including "C" and "").
std::string language_for_locale(std::string_view locale);

}  // namespace swarmlab
