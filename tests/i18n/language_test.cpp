#include "i18n/language.h"

#include <doctest/doctest.h>

using namespace swarmlab;

TEST_CASE("six languages, English first, each with its decimal separator") {
  REQUIRE(languages().size() == 6);
  CHECK(languages().front().code == "en");
  CHECK(find_language("de")->decimal_separator == ',');
  CHECK(find_language("zh-CN")->decimal_separator == '.');
  CHECK(find_language("zh-CN")->needs_cjk_font);
  CHECK_FALSE(find_language("fr")->needs_cjk_font);
  CHECK(find_language("x-pseudo") == &pseudo_language());
  CHECK_FALSE(find_language("ar"));
  CHECK_FALSE(find_language("ES"));  // codes are exact; locales go through language_for_locale
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
}
