#pragma once
// A lesson file breaks a rule: "field: rule", thrown while a lesson or its claims are read and
// caught once, where the reader turns it into its one message (lesson.cpp, lesson_claim.cpp).

#include <string>

namespace swarmlab::field_rule {

struct Broken {
  std::string message;
};

[[noreturn]] inline void fail(const std::string& field, const std::string& rule) {
  throw Broken{field + ": " + rule};
}

inline void require(bool ok, const std::string& field, const std::string& rule) {
  if (!ok) fail(field, rule);
}

}  // namespace swarmlab::field_rule
