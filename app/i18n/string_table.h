#pragma once
/// One language's strings: for every English text the app shows, the text to show instead.
/// The English text itself is the key (as gettext's msgid), so the sources read as they always
/// did and a string whose English changes has no translation until a translator gives one:
/// the English shows meanwhile, never a stale sentence.

#include <string>
#include <string_view>
#include <unordered_map>

namespace swarmlab {

class StringTable {
 public:
  /// Reads a table: one JSON object whose keys are English texts and whose values are their
  /// translations, both strings. On failure the table is empty and `error` names the key and
  /// the rule it breaks.
  static StringTable parse(std::string_view json, std::string& error);

  /// The translation of `english`, or null when the table has none (a missing or empty one).
  const std::string* find(std::string_view english) const;
  std::size_t size() const { return strings_.size(); }

 private:
  std::unordered_map<std::string, std::string> strings_;
};

}  // namespace swarmlab
