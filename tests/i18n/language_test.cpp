#include "i18n/language.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <set>

using namespace swarmlab;

TEST_CASE("six languages, English first, each with its decimal separator") {
  REQUIRE(languages().size() == 6);
  CHECK(languages().front().code == "en");
  CHECK(&source_language() == &languages().front());
  CHECK(find_language("de")->decimal_separator == ',');
  CHECK(find_language("zh-CN")->decimal_separator == '.');
  CHECK(find_language("zh-CN")->needs_cjk_font);
  CHECK_FALSE(find_language("fr")->needs_cjk_font);
  CHECK(find_language("x-pseudo") == &pseudo_language());
  CHECK(pseudo_language().pseudo);
  CHECK(std::none_of(languages().begin(), languages().end(), [](const Language& l) { return l.pseudo; }));
  CHECK_FALSE(find_language("ar"));
  CHECK_FALSE(find_language("ES"));  // codes are exact; locales go through language_for_locale
}

TEST_CASE("every language in the table has its table in assets/i18n/, and every table its language") {
  std::set<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(SWARM_I18N_DIR))
    if (entry.path().extension() == ".json" && entry.path().filename() != "languages.json")
      files.insert(entry.path().stem().string());
  std::set<std::string> listed;
  for (const Language& l : languages()) listed.insert(l.code);  // English's is the keys (en.json)
  CHECK(files == listed);
  // The pseudo-language makes its texts from the English: a table for it would never be read.
  CHECK_FALSE(files.count(pseudo_language().code));
  CHECK(listed.size() == languages().size());  // no code twice
}

TEST_CASE("a locale picks the closest language, English when none fits") {
  CHECK(language_for_locale("es-MX") == "es");
  CHECK(language_for_locale("es_ES.UTF-8") == "es");
  CHECK(language_for_locale("de_AT.UTF-8@euro") == "de");
  CHECK(language_for_locale("FR-ca") == "fr");
  CHECK(language_for_locale("pt") == "pt-BR");
  CHECK(language_for_locale("pt-PT") == "pt-BR");
  CHECK(language_for_locale("zh-Hans-CN") == "zh-CN");
  CHECK(language_for_locale("zh_TW") == "zh-CN");
  CHECK(language_for_locale("en-GB") == "en");
  CHECK(language_for_locale("ar-EG") == "en");
  CHECK(language_for_locale("C") == "en");
  CHECK(language_for_locale("") == "en");
  CHECK(language_for_locale("x-pseudo") == "en");  // only its code chooses the pseudo-language
}

TEST_CASE("the alias rule: a locale whose primary subtag is a language's alias gets that language") {
  for (const Language& l : languages()) {
    CAPTURE(l.code);
    CHECK_FALSE(l.aliases.empty());  // every listed language is someone's locale
    for (const std::string& alias : l.aliases) {
      CAPTURE(alias);
      std::string upper = alias;
      for (char& c : upper) c = char(c - 'a' + 'A');
      CHECK(language_for_locale(alias) == l.code);
      CHECK(language_for_locale(upper + "-XY") == l.code);
      CHECK(language_for_locale(alias + "_XY.UTF-8@euro") == l.code);
      CHECK(language_for_locale(alias + "x") == source_language().code);  // a whole subtag, not a prefix
    }
  }
  // Each listed code, given as a locale, comes back: its own primary subtag is among its aliases.
  for (const Language& l : languages()) CHECK(language_for_locale(l.code) == l.code);
}

TEST_CASE("the codes for a help text come from the table") {
  CHECK(language_codes() == "en, es, de, fr, pt-BR, zh-CN");
  CHECK(language_codes("\"", true) == "\"es\", \"de\", \"fr\", \"pt-BR\", \"zh-CN\"");
}
