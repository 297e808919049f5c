#include "i18n/string_table.h"

#include <doctest/doctest.h>

using namespace swarmlab;

TEST_CASE("a string table maps English texts to translations; empty ones count as missing") {
  std::string error;
  const StringTable t = StringTable::parse(R"({"Pause": "Pausa", "Play": "", "t = %.3f": "t = %.3f"})", error);
  CHECK(error.empty());
  REQUIRE(t.find("Pause"));
  CHECK(*t.find("Pause") == "Pausa");
  CHECK_FALSE(t.find("Play"));  // empty: the English shows
  CHECK_FALSE(t.find("Reset"));
  CHECK(t.size() == 2);
}

TEST_CASE("a table that does not read names the rule and stays empty") {
  std::string error;
  CHECK(StringTable::parse("{", error).size() == 0);
  CHECK(error == "not valid JSON");
  CHECK(StringTable::parse("[1]", error).size() == 0);
  CHECK(error == "must be a JSON object of English texts to their translations");
  CHECK(StringTable::parse(R"({"Pause": "Pausa", "Play": 3})", error).size() == 0);
  CHECK(error == "\"Play\": the translation must be a string");
}
