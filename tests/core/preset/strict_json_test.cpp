#include "swarm/preset/strict_json.h"

#include <doctest/doctest.h>

#include <string>

using swarm::DuplicateKey;
using swarm::parse_strict_json;

namespace {

/// The message of the DuplicateKey that text raises, or "" when it parses.
std::string duplicate_in(const std::string& text) {
  try {
    parse_strict_json(text);
  } catch (const DuplicateKey& e) {
    return e.what();
  }
  return {};
}

}  // namespace

TEST_CASE("strict JSON reads what nlohmann's plain parser reads, when no key repeats") {
  const std::string text = R"({"J": -0.5, "n": 3, "big": 18446744073709551615, "ok": true,
    "none": null, "name": "Zwei Körper", "particles": [{"m": 1, "r": [0, 1e-3, -2]},
    {"m": 2.5, "r": [[], {}], "v": {"x": 1}}], "m": 7})";
  CHECK(parse_strict_json(text) == nlohmann::json::parse(text));
  // The same key in sibling objects and at different depths is not a repeat.
  CHECK(duplicate_in(R"([{"a": 1}, {"a": 2, "b": {"a": 3}}])").empty());
}

TEST_CASE("a key given twice in one object is named by its path") {
  CHECK(duplicate_in(R"({"a": 1, "a": 2})") == "a: given twice (each key at most once)");
  CHECK(duplicate_in(R"({"x": [0, {"y": [[1], [{"b": 1, "c": 2, "b": 3}]]}]})") ==
        "x[1].y[1][0].b: given twice (each key at most once)");
  // Keys are compared as decoded text: an escape spells the same key.
  CHECK(duplicate_in(R"({"m": 1, "\u006d": 2})") == "m: given twice (each key at most once)");
}

TEST_CASE("an object of many keys: each repeat found, whether early or late") {
  // A hostile link may hold one object of a hundred thousand keys (compared in pairs, that
  // would be 5e9 comparisons); the first and the last key repeated, and none repeated.
  std::string keys;
  for (int i = 0; i < 100000; ++i) keys += "\"k" + std::to_string(i) + "\": 0, ";
  CHECK(duplicate_in("{" + keys + "\"k0\": 1}") == "k0: given twice (each key at most once)");
  CHECK(duplicate_in("{\"x\": [{" + keys + "\"k99999\": 1}]}") ==
        "x[0].k99999: given twice (each key at most once)");
  const nlohmann::json unique = parse_strict_json("{" + keys + "\"last\": 1}");
  CHECK(unique.size() == 100001);
  CHECK(unique.at("k54321") == 0);
}

TEST_CASE("text that is not exactly one JSON value is refused as nlohmann refuses it") {
  CHECK_THROWS_AS(parse_strict_json(R"({"a": 1} {"b": 2})"), nlohmann::json::parse_error);
  CHECK_THROWS_AS(parse_strict_json(R"({"a": 1,})"), nlohmann::json::parse_error);
  CHECK_THROWS_AS(parse_strict_json(""), nlohmann::json::parse_error);
}
