#include "i18n/language_table.h"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>

#include "i18n/embedded_tables.h"

using namespace swarmlab;
using nlohmann::ordered_json;

namespace {

std::string shipped_text() {
  std::ifstream in(std::string(SWARM_I18N_DIR) + "/languages.json", std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The error for the shipped table after `change`, "" when it reads.
template <class Change>
std::string error_after(Change change) {
  ordered_json table = ordered_json::parse(shipped_text());
  change(table);
  std::string error;
  const std::vector<Language> read = read_language_table(table.dump(), error);
  CHECK(read.empty() == !error.empty());
  return error;
}

}  // namespace

TEST_CASE("the table built into the program is assets/i18n/languages.json as it is now, and reads") {
  CHECK(embedded_language_table() == shipped_text());
  std::string error;
  const std::vector<Language> rows = read_language_table(embedded_language_table(), error);
  CHECK(error == "");
  REQUIRE(rows.size() == 7);
  CHECK(rows[4].code == "pt-BR");
  CHECK(rows[4].native_name == "Português (Brasil)");
  CHECK(rows[4].decimal_separator == ',');
  CHECK(rows[4].aliases == std::vector<std::string>{"pt"});
  CHECK(rows[5].needs_cjk_font);
  CHECK(rows[6].pseudo);
}

TEST_CASE("a malformed table is refused, naming the row, the field and the rule") {
  CHECK(error_after([](ordered_json&) {}) == "");
  CHECK(error_after([](ordered_json& t) { t[5]["decimal_separator"] = ";"; }) ==
        "[5].decimal_separator: must be \".\" or \",\"");
  CHECK(error_after([](ordered_json& t) { t[2].erase("font"); }) ==
        "[2].font: missing (every language has all seven fields)");
  CHECK(error_after([](ordered_json& t) { t[3]["font"] = "Arial"; }).rfind("[3].font: must be \"DejaVu Sans\"", 0) == 0);
  CHECK(error_after([](ordered_json& t) { t[1]["fnot"] = "x"; }).rfind("[1].fnot: not a field of a language", 0) == 0);
  CHECK(error_after([](ordered_json& t) { t[1]["code"] = "../es"; }).rfind("[1].code: must be a BCP 47 language tag", 0) == 0);
  CHECK(error_after([](ordered_json& t) { t[1]["code"] = "de"; }) == "[2].code: \"de\" is row 1's code already");
  CHECK(error_after([](ordered_json& t) { t[1]["native_name"] = "Espa\nñol"; }).rfind("[1].native_name: must be", 0) == 0);
  CHECK(error_after([](ordered_json& t) { t[4]["aliases"] = {"PT"}; }).rfind("[4].aliases[0]: must be a primary language subtag", 0) == 0);
  CHECK(error_after([](ordered_json& t) { t[4]["aliases"] = {"pt", "es"}; }) ==
        "[4].aliases: \"es\" is an alias of es already");
  CHECK(error_after([](ordered_json& t) { t[6]["aliases"] = {"xx"}; }).rfind("[6].aliases: must be [] for the pseudo-language", 0) == 0);
  CHECK(error_after([](ordered_json& t) { t[6]["pseudo"] = "yes"; }) == "[6].pseudo: must be true or false");
  CHECK(error_after([](ordered_json& t) { t[6]["pseudo"] = false; }).rfind("pseudo: one language must be the pseudo-language", 0) == 0);
  CHECK(error_after([](ordered_json& t) { t[1]["pseudo"] = true; t[1]["aliases"] = ordered_json::array(); }) ==
        "[6].pseudo: row 1 is the pseudo-language already");
  CHECK(error_after([](ordered_json& t) { t.erase(0); t[5]["pseudo"] = false; t[0]["pseudo"] = true;
                                          t[0]["aliases"] = ordered_json::array(); })
            .rfind("[0].pseudo: the first language is the one the texts are written in", 0) == 0);
  CHECK(error_after([](ordered_json& t) { t[2]["same_as_english"] = {1}; }) == "[2].same_as_english[0]: must be a text");
  CHECK(error_after([](ordered_json& t) { t = ordered_json::object(); }).rfind("must be a JSON array of languages", 0) == 0);
  std::string error;
  CHECK(read_language_table("[{", error).empty());
  CHECK(error == "not valid JSON");
}
