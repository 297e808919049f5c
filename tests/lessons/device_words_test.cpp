#include "lessons/device_words.h"

#include <doctest/doctest.h>

using namespace swarmlab;

TEST_CASE("device words: each choice reads as the student's input would do it") {
  const char* text = "{Tap|Click} a ball, then {tap *Play*|click *Play*|press *Space*}.";
  CHECK(device_words(text, InputKind::touch) == "Tap a ball, then tap *Play*.");
  CHECK(device_words(text, InputKind::mouse) == "Click a ball, then click *Play*.");
  CHECK(device_words(text, InputKind::keyboard) == "Click a ball, then press *Space*.");
}

TEST_CASE("device words: text without a choice is kept as it is, broken braces too") {
  CHECK(device_words("F = J m r", InputKind::touch) == "F = J m r");
  CHECK(device_words("", InputKind::keyboard).empty());
  // The validator refuses these; drawn anyway, they are not swallowed.
  CHECK(device_words("{tap} and {a|b", InputKind::mouse) == "{tap} and {a|b");
}

TEST_CASE("device words: the rule is 2 or 3 non-empty alternatives closed on their line") {
  CHECK(device_words_problem("no braces").empty());
  CHECK(device_words_problem("{tap|click} and {a|b|c}").empty());
  CHECK_FALSE(device_words_problem("{tap}").empty());
  CHECK_FALSE(device_words_problem("{a|b|c|d}").empty());
  CHECK_FALSE(device_words_problem("{a||b}").empty());
  CHECK_FALSE(device_words_problem("{a|b").empty());
  CHECK_FALSE(device_words_problem("{a|\nb}").empty());
  CHECK_FALSE(device_words_problem("{a|{b|c}}").empty());
  CHECK(device_words_problem("a } b").rfind("a '}' with no '{' before it", 0) == 0);
  // Each alternative is drawn alone: its emphasis must close inside it.
  CHECK(device_words_problem("{tap *Play|click Play*}").rfind("an emphasis is not closed", 0) == 0);
  CHECK(device_words_problem("{tap *Play*|click *Play*}").empty());
}
