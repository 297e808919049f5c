#pragma once
/// The language the front end speaks now, and the texts it shows in it. Every string the UI
/// shows passes through tr() (text) or tr_id() (an ImGui item's label); the tables are
/// assets/i18n/<code>.json, whose keys are the English texts (docs/i18n.md).

#include <map>
#include <string>
#include <string_view>
#include <unordered_map>

#include "i18n/language.h"
#include "i18n/string_table.h"

namespace swarmlab {

class Translator {
 public:
  Translator();
  /// Speaks `language` from `table` (English needs none; the pseudo-language makes its own).
  void use(const Language& language, StringTable table);
  const Language& language() const { return language_; }
  /// Texts consulted before the table: an open lesson's own translations into this language
  /// (docs/lessons.md), kept as a copy; `source` names them (the lesson's id), so passing the
  /// same source again costs nothing. An empty source removes them.
  void use_lesson_texts(const std::string& source, const std::map<std::string, std::string>* texts);

  /// The text to show for `english`: its translation, or `english` itself when the table has
  /// none. The pointer stays valid until the next use().
  const char* text(const char* english);
  /// An ImGui item's label: the text to show, then "###" and the English label, so the item
  /// keeps one ID (its open state, its focus, the parallel DOM's identity) in every language.
  /// "Open##preset" shows text("Open") with the ID of "###Open##preset".
  const char* label(const char* english);
  /// The English label a label() came from (a window's name as ImGui keeps it), or `shown`
  /// itself when label() did not make it: what swarmlab.state() reports, in every language.
  std::string_view english_label(std::string_view shown) const;
  /// Printed text with every decimal point between two digits written as the language's
  /// separator: "t = 7.5" reads "t = 7,5" in Spanish.
  std::string numbers(std::string printed) const;

 private:
  Language language_;
  StringTable table_;
  // Made on first use and kept until the language changes; unordered_map keeps its values in
  // place as it grows, so the pointers handed out stay valid.
  std::unordered_map<std::string, std::string> pseudo_, labels_;
  std::unordered_map<std::string, std::string> english_labels_;  // label() -> its English
  std::string lesson_source_;
  std::map<std::string, std::string> lesson_texts_;
};

/// The pseudo-language's text for `english`: letters accented, the text padded to about 1.6x
/// its length inside brackets, while printf conversions (%.4g), device choices ({tap|click}
/// keeps its braces and bars) and line breaks stay as they are, so layouts can be tested
/// against long translations and every placeholder still works.
std::string pseudo_text(std::string_view english);

/// Marks a text for the tables where it is defined (an array of labels, say) and shown through
/// tr() or tr_id() later, as gettext's N_(): scripts/i18n.py extract finds it.
constexpr const char* tr_noop(const char* english) { return english; }

/// The front end's translator (one UI thread).
Translator& translator();
inline const char* tr(const char* english) { return translator().text(english); }
inline const char* tr_id(const char* english) { return translator().label(english); }

}  // namespace swarmlab
