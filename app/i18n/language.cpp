#include "i18n/language.h"

#include <cctype>
#include <cstdio>
#include <cstdlib>

#include "i18n/embedded_tables.h"
#include "i18n/language_table.h"

namespace swarmlab {
namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = char(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

/// Every row of the built-in table, the pseudo-language's included. The table is part of the
/// build and the unit tests read it, so one that does not read is a broken build: it stops here
/// with the reason rather than running without languages.
const std::vector<Language>& rows() {
  static const std::vector<Language> all = [] {
    std::string error;
    std::vector<Language> read = read_language_table(embedded_language_table(), error);
    if (!error.empty()) {
      std::fprintf(stderr, "error: assets/i18n/languages.json (built in): %s\n", error.c_str());
      std::exit(70);  // EX_SOFTWARE
    }
    return read;
  }();
  return all;
}

}  // namespace

const std::vector<Language>& languages() {
  static const std::vector<Language> listed = [] {
    std::vector<Language> out;
    for (const Language& l : rows())
      if (!l.pseudo) out.push_back(l);
    return out;
  }();
  return listed;
}

const Language& source_language() { return languages().front(); }

const Language& pseudo_language() {
  for (const Language& l : rows())
    if (l.pseudo) return l;
  return rows().front();  // not reached: the table holds one (language_table.cpp)
}

const Language* find_language(std::string_view code) {
  for (const Language& l : languages())
    if (l.code == code) return &l;
  return code == pseudo_language().code ? &pseudo_language() : nullptr;
}

std::string language_for_locale(std::string_view locale) {
  // A POSIX locale or a browser's tag, "ab_CD.UTF-8@euro" or "AB-cd", to its primary subtag "ab".
  std::string tag = lower(locale.substr(0, locale.find_first_of(".@")));
  for (char& c : tag)
    if (c == '_') c = '-';
  const std::string primary = tag.substr(0, tag.find('-'));
  for (const Language& l : languages())
    for (const std::string& alias : l.aliases)
      if (alias == primary) return l.code;
  return source_language().code;
}

std::string language_codes(std::string_view quote, bool translations_only) {
  std::string out;
  for (const Language& l : languages()) {
    if (translations_only && &l == &source_language()) continue;
    if (!out.empty()) out += ", ";
    out.append(quote).append(l.code).append(quote);
  }
  return out;
}

}  // namespace swarmlab
