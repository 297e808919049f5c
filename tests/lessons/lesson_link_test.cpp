#include "lessons/lesson_link.h"

#include <doctest/doctest.h>

#include <string>
#include <vector>

using namespace swarmlab;

namespace {
const std::vector<std::string> kShipped = {"one-period", "springs-to-cm"};
}

TEST_CASE("base64url: RFC 4648 section 5's test vectors, without padding, both ways") {
  const char* plain[] = {"", "f", "fo", "foo", "foob", "fooba", "foobar"};
  const char* coded[] = {"", "Zg", "Zm8", "Zm9v", "Zm9vYg", "Zm9vYmE", "Zm9vYmFy"};
  for (int i = 0; i < 7; ++i) {
    CHECK(to_base64url(plain[i]) == coded[i]);
    std::string back;
    if (i > 0) {
      REQUIRE(from_base64url(coded[i], &back));
      CHECK(back == plain[i]);
    }
  }
  // The two characters that differ from plain base64, and its padding, are read too.
  std::string bytes;
  REQUIRE(from_base64url("-_8=", &bytes));
  CHECK(bytes == "\xfb\xff");
  REQUIRE(from_base64url("+/8", &bytes));
  CHECK(bytes == "\xfb\xff");
  CHECK_FALSE(from_base64url("Zm9v!", &bytes));
  CHECK_FALSE(from_base64url("Z", &bytes));
  CHECK_FALSE(from_base64url("Zg=x", &bytes));
}

TEST_CASE("a lesson link names a shipped lesson by id and carries any other as JSON") {
  CHECK(lesson_link_fragment("one-period", "{}") == "#lesson=one-period");
  const std::string json = R"({"lesson": 1, "id": "mine"})";
  const std::string fragment = lesson_link_fragment("", json);
  REQUIRE(fragment.rfind("#lesson=", 0) == 0);
  // What the button writes is what the page reads back.
  const LessonLinkTarget custom = read_lesson_link(fragment.substr(8), kShipped);
  CHECK(custom.error.empty());
  CHECK(custom.json == json);
  const LessonLinkTarget shipped = read_lesson_link("one-period", kShipped);
  CHECK(shipped.id == "one-period");
  CHECK(shipped.json.empty());
}

TEST_CASE("a lesson link that is neither form is refused in one sentence") {
  const std::string sentence =
      "the text after #lesson= is neither a shipped lesson's id (one-period, springs-to-cm) nor "
      "a lesson written by Share (its JSON in base64url); the link may have been cut short";
  // The finding: base64url of a shipped id is not what the button writes.
  CHECK(read_lesson_link(to_base64url("one-period"), kShipped).error == sentence);
  CHECK(read_lesson_link("no-such-lesson", kShipped).error == sentence);
  CHECK(read_lesson_link("", kShipped).error == sentence);
  CHECK(read_lesson_link("%%%", kShipped).error == sentence);
  CHECK(read_lesson_link(to_base64url("[1, 2]"), kShipped).error == sentence);
  // Lesson JSON that is cut short is still read as a lesson: parse_lesson names what broke.
  const std::string cut = to_base64url(R"({"lesson": 1, "id": "a)");
  CHECK(read_lesson_link(cut, kShipped).json == R"({"lesson": 1, "id": "a)");
}
