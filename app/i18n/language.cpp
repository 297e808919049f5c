#include "i18n/language.h"

#include <cctype>

namespace swarmlab {
namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = char(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

}  // namespace

const std::vector<Language>& languages() {
  static const std::vector<Language> all = {
      {"en", "English", '.', false},
      {"es", "Español", ',', false},
      {"de", "Deutsch", ',', false},
      {"fr", "Français", ',', false},
      {"pt-BR", "Português (Brasil)", ',', false},
      {"zh-CN", "中文（简体）", '.', true},
  };
  return all;
}

const Language& pseudo_language() {
  static const Language pseudo{"x-pseudo", "Ƥšéûðö", ',', false};
  return pseudo;
}

const Language* find_language(std::string_view code) {
  for (const Language& l : languages())
    if (l.code == code) return &l;
  if (code == pseudo_language().code) return &pseudo_language();
  return nullptr;
}

std::string language_for_locale(std::string_view locale) {
  // "es_ES.UTF-8@euro" -> "es-es"; the primary subtag decides, except for Chinese scripts.
  std::string tag = lower(locale.substr(0, locale.find_first_of(".@")));
  for (char& c : tag)
    if (c == '_') c = '-';
  const std::string primary = tag.substr(0, tag.find('-'));
  if (primary == "pt") return "pt-BR";
  if (primary == "zh") return "zh-CN";  // Simplified is the one offered; Traditional reads it
  for (const Language& l : languages())
    if (l.code == primary) return l.code;
  return "en";
}

}  // namespace swarmlab
