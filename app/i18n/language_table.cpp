#include "i18n/language_table.h"

#include <cctype>

#include <nlohmann/json.hpp>

namespace swarmlab {
namespace {

using nlohmann::json;

const char* const kFields[] = {"code", "native_name", "decimal_separator", "aliases", "pseudo", "font",
                               "same_as_english"};

/// The fonts the app can draw with: the UI's own, always built in, and the Chinese subset,
/// loaded only for a language that needs it (app/ui/platform/fonts.cpp).
constexpr std::string_view kUiFont = "DejaVu Sans", kCjkFont = "Noto Sans CJK SC";

/// BCP 47's shape, enough for a file name: parts of 1 to 8 letters or digits joined by '-', the
/// first of letters only (a region or a private use after the language).
bool is_language_tag(const std::string& s) {
  std::size_t part = 0;
  bool first = true;
  for (char c : s) {
    if (c == '-') {
      if (part == 0) return false;
      part = 0;
      first = false;
    } else if (std::isalpha(static_cast<unsigned char>(c)) || (!first && std::isdigit(static_cast<unsigned char>(c)))) {
      if (++part > 8) return false;
    } else {
      return false;
    }
  }
  return part > 0;
}

/// A primary language subtag as aliases hold it: 2 or 3 lower-case letters.
bool is_primary_subtag(const std::string& s) {
  if (s.size() < 2 || s.size() > 3) return false;
  for (char c : s)
    if (c < 'a' || c > 'z') return false;
  return true;
}

bool has_control_character(const std::string& s) {
  for (unsigned char c : s)
    if (c < 0x20 || c == 0x7F) return true;
  return false;
}

/// Reads one row into `l`; the error names the field, after "[row].".
std::string read_row(const json& row, Language& l) {
  if (!row.is_object()) return ": must be an object with the fields code, native_name, decimal_separator, "
                               "aliases, pseudo, font and same_as_english";
  for (const auto& [name, value] : row.items()) {
    bool known = false;
    for (const char* f : kFields) known = known || name == f;
    if (!known)
      return "." + name + ": not a field of a language (code, native_name, decimal_separator, aliases, pseudo, "
             "font, same_as_english)";
  }
  for (const char* f : kFields)
    if (!row.contains(f)) return std::string(".") + f + ": missing (every language has all seven fields)";

  const json& code = row["code"];
  if (!code.is_string() || !is_language_tag(code.get<std::string>()))
    return ".code: must be a BCP 47 language tag (parts of 1 to 8 letters or digits joined by '-', the "
           "first of letters), the name of its table assets/i18n/<code>.json";
  l.code = code.get<std::string>();

  const json& name = row["native_name"];
  if (!name.is_string() || name.get<std::string>().empty() || has_control_character(name.get<std::string>()))
    return ".native_name: must be the language's name as its readers write it (text, without control "
           "characters)";
  l.native_name = name.get<std::string>();

  const json& separator = row["decimal_separator"];
  if (separator != "." && separator != ",") return ".decimal_separator: must be \".\" or \",\"";
  l.decimal_separator = separator.get<std::string>()[0];

  const json& aliases = row["aliases"];
  if (!aliases.is_array()) return ".aliases: must be an array of primary language subtags such as [\"pt\"]";
  for (std::size_t k = 0; k < aliases.size(); ++k) {
    if (!aliases[k].is_string() || !is_primary_subtag(aliases[k].get<std::string>()))
      return ".aliases[" + std::to_string(k) + "]: must be a primary language subtag in lower case, 2 or 3 "
             "letters (\"pt\" stands for pt, pt-PT, pt_BR.UTF-8 ...)";
    l.aliases.push_back(aliases[k].get<std::string>());
  }

  if (!row["pseudo"].is_boolean()) return ".pseudo: must be true or false";
  l.pseudo = row["pseudo"].get<bool>();
  if (l.pseudo && !l.aliases.empty())
    return ".aliases: must be [] for the pseudo-language, which only its code (#lang=) chooses";

  const json& font = row["font"];
  if (font != kUiFont && font != kCjkFont)
    return ".font: must be \"DejaVu Sans\" (the UI's font) or \"Noto Sans CJK SC\" (Chinese glyphs)";
  l.needs_cjk_font = font == kCjkFont;

  const json& same = row["same_as_english"];
  if (!same.is_array()) return ".same_as_english: must be an array of English texts";
  for (std::size_t k = 0; k < same.size(); ++k)
    if (!same[k].is_string()) return ".same_as_english[" + std::to_string(k) + "]: must be a text";
  return {};
}

}  // namespace

std::vector<Language> read_language_table(std::string_view text, std::string& error) {
  error.clear();
  const json j = json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded()) {
    error = "not valid JSON";
    return {};
  }
  if (!j.is_array() || j.empty()) {
    error = "must be a JSON array of languages, one object each, the language of the texts first";
    return {};
  }
  std::vector<Language> out;
  std::size_t pseudo_row = j.size();
  for (std::size_t i = 0; i < j.size(); ++i) {
    const std::string row = "[" + std::to_string(i) + "]";
    Language l;
    if (std::string e = read_row(j[i], l); !e.empty()) {
      error = row + e;
      return {};
    }
    for (std::size_t k = 0; k < out.size(); ++k) {
      if (out[k].code == l.code) {
        error = row + ".code: \"" + l.code + "\" is row " + std::to_string(k) + "'s code already";
        return {};
      }
      for (const std::string& a : l.aliases)
        for (const std::string& b : out[k].aliases)
          if (a == b) {
            error = row + ".aliases: \"" + a + "\" is an alias of " + out[k].code + " already";
            return {};
          }
    }
    if (l.pseudo && i == 0) {
      error = row + ".pseudo: the first language is the one the texts are written in, not the pseudo-language";
      return {};
    }
    if (l.pseudo && pseudo_row < j.size()) {
      error = row + ".pseudo: row " + std::to_string(pseudo_row) + " is the pseudo-language already";
      return {};
    }
    if (l.pseudo) pseudo_row = i;
    out.push_back(std::move(l));
  }
  if (pseudo_row == j.size()) {
    error = "pseudo: one language must be the pseudo-language (\"pseudo\": true), for the layout tests";
    return {};
  }
  return out;
}

}  // namespace swarmlab
