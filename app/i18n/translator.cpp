#include "i18n/translator.h"

#include <cctype>
#include <cmath>

namespace swarmlab {
namespace {

/// The accented form of an ASCII letter, in Latin-1 (which the UI font always holds).
const char* accented(char c) {
  switch (c) {
    case 'a': return "à";
    case 'e': return "é";
    case 'i': return "î";
    case 'o': return "õ";
    case 'u': return "ü";
    case 'c': return "ç";
    case 'n': return "ñ";
    case 'y': return "ý";
    case 'A': return "Å";
    case 'E': return "É";
    case 'I': return "Î";
    case 'O': return "Ö";
    case 'U': return "Û";
    case 'C': return "Ç";
    case 'N': return "Ñ";
    default: return nullptr;
  }
}

/// The length of the printf conversion at s[0] == '%': flags, width, precision, length, type.
std::size_t conversion_length(std::string_view s) {
  std::size_t i = 1;
  while (i < s.size() && std::string_view("-+ #0123456789.*hlLzjt").find(s[i]) != std::string_view::npos) ++i;
  return i < s.size() ? i + 1 : i;
}

/// Counts UTF-8 characters (not continuation bytes).
std::size_t characters(std::string_view s) {
  std::size_t n = 0;
  for (unsigned char c : s) n += (c & 0xC0) != 0x80;
  return n;
}

}  // namespace

std::string pseudo_text(std::string_view english) {
  std::string out = "[";
  for (std::size_t i = 0; i < english.size();) {
    const char c = english[i];
    if (c == '%') {
      const std::size_t n = conversion_length(english.substr(i));
      out.append(english.substr(i, n));
      i += n;
    } else if (const char* a = accented(c)) {
      out += a;
      ++i;
    } else {
      out += c;
      ++i;
    }
  }
  // Pad each text to about 1.6x its length, as German or French often are; short words grow
  // most in real translations, so at least three more characters.
  const std::size_t length = characters(english);
  const std::size_t extra = std::max<std::size_t>(3, std::size_t(std::ceil(0.6 * double(length))));
  static const char* const filler[] = {"ë", "ï", "ô", "â", "û", " "};
  for (std::size_t k = 0; k < extra; ++k) out += filler[k % 6];
  out += "]";
  return out;
}

Translator::Translator() : language_(languages().front()) {}

void Translator::use(const Language& language, StringTable table) {
  language_ = language;
  table_ = std::move(table);
  lesson_source_.clear();  // another language: the lesson's texts in it are set again
  lesson_texts_.clear();
  pseudo_.clear();
  labels_.clear();
  english_labels_.clear();
}

void Translator::use_lesson_texts(const std::string& source,
                                  const std::map<std::string, std::string>* texts) {
  if (source == lesson_source_) return;
  lesson_source_ = source;
  lesson_texts_ = texts ? *texts : std::map<std::string, std::string>{};
  labels_.clear();  // labels made from the old texts
  english_labels_.clear();
}

const char* Translator::text(const char* english) {
  if (!lesson_texts_.empty())
    if (const auto it = lesson_texts_.find(english); it != lesson_texts_.end())
      return it->second.c_str();
  if (language_.code == pseudo_language().code) {
    auto it = pseudo_.find(english);
    if (it == pseudo_.end()) it = pseudo_.emplace(english, pseudo_text(english)).first;
    return it->second.c_str();
  }
  const std::string* shown = table_.find(english);
  return shown ? shown->c_str() : english;
}

const char* Translator::label(const char* english) {
  auto it = labels_.find(english);
  if (it != labels_.end()) return it->second.c_str();
  const std::string_view whole(english);
  const std::size_t id = whole.find("##");
  std::string made;
  if (id == 0) {
    made = whole;  // nothing shown: the ID alone
  } else {
    const std::string visible(whole.substr(0, id));
    made = text(visible.c_str());
    if (id != std::string_view::npos && whole.compare(id, 3, "###") == 0)
      made += whole.substr(id);  // already an ID of its own
    else
      made += "###" + std::string(whole);
  }
  english_labels_.emplace(made, english);
  return labels_.emplace(english, std::move(made)).first->second.c_str();
}

std::string_view Translator::english_label(std::string_view shown) const {
  const auto it = english_labels_.find(std::string(shown));
  return it == english_labels_.end() ? shown : std::string_view(it->second);
}

std::string Translator::numbers(std::string printed) const {
  const char separator = language_.decimal_separator;
  if (separator == '.') return printed;
  for (std::size_t i = 1; i + 1 < printed.size(); ++i)
    if (printed[i] == '.' && std::isdigit(static_cast<unsigned char>(printed[i - 1])) &&
        std::isdigit(static_cast<unsigned char>(printed[i + 1])))
      printed[i] = separator;
  return printed;
}

Translator& translator() {
  static Translator t;
  return t;
}

}  // namespace swarmlab
