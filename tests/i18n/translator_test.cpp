#include "i18n/translator.h"

#include <doctest/doctest.h>

#include <regex>
#include <string>

using namespace swarmlab;

namespace {

Translator spanish() {
  std::string error;
  Translator t;
  t.use(*find_language("es"),
        StringTable::parse(R"({"Pause": "Pausa", "Open": "Abrir", "t = %.3f": "t = %.3f s"})", error));
  return t;
}

}  // namespace

TEST_CASE("the translator shows the translation, or the English when the table lacks it") {
  Translator t = spanish();
  CHECK(std::string(t.text("Pause")) == "Pausa");
  const char* english = "Reset";
  CHECK(t.text(english) == english);  // the very same text, not a copy
  Translator plain;
  CHECK(plain.language().code == "en");
  CHECK(std::string(plain.text("Pause")) == "Pause");
}

TEST_CASE("labels keep the English ID in every language") {
  Translator t = spanish();
  CHECK(std::string(t.label("Pause")) == "Pausa###Pause");
  CHECK(std::string(t.label("Open##preset")) == "Abrir###Open##preset");
  CHECK(std::string(t.label("Open###file")) == "Abrir###file");
  CHECK(std::string(t.label("##speed")) == "##speed");
  CHECK(std::string(t.label("Reset")) == "Reset###Reset");
  CHECK(t.english_label("Abrir###Open##preset") == "Open##preset");
  CHECK(t.english_label("Controls") == "Controls");  // not made by label(): as it is
  Translator plain;
  CHECK(std::string(plain.label("Pause")) == "Pause###Pause");  // the same ID as in Spanish
}

TEST_CASE("numbers take the language's decimal separator, only between digits") {
  Translator t = spanish();
  CHECK(t.numbers("t = 7.500, e.g. 1.2e+05 and 3.") == "t = 7,500, e.g. 1,2e+05 and 3.");
  Translator plain;
  CHECK(plain.numbers("t = 7.500") == "t = 7.500");
}

TEST_CASE("the pseudo-language: longer, accented, with every placeholder intact") {
  const std::string english = "{tap|click} *Play*: t = %.3f of %d steps\nagain 100%%";
  const std::string pseudo = pseudo_text(english);
  CHECK(pseudo.front() == '[');
  CHECK(pseudo.back() == ']');
  // The printf conversions, the device choice and the line break are where they were.
  std::smatch m;
  CHECK(pseudo.find("%.3f") != std::string::npos);
  CHECK(pseudo.find("%d") != std::string::npos);
  CHECK(pseudo.find("%%") != std::string::npos);
  CHECK(std::regex_search(pseudo, m, std::regex(R"(\{[^|{}]+\|[^|{}]+\})")));
  CHECK(pseudo.find('\n') != std::string::npos);
  CHECK(pseudo.find("Plàý") != std::string::npos);  // accented
  // About 1.6x as long in characters.
  auto characters = [](const std::string& s) {
    std::size_t n = 0;
    for (unsigned char c : s) n += (c & 0xC0) != 0x80;
    return n;
  };
  CHECK(characters(pseudo) >= characters(english) * 16 / 10);
  Translator t;
  t.use(pseudo_language(), {});
  CHECK(std::string(t.text("Pause")) == pseudo_text("Pause"));
}
