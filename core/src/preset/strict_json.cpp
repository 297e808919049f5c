#include "swarm/preset/strict_json.h"

#include <algorithm>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

#include "swarm/preset/printable_text.h"

namespace swarm {
namespace {

using json = nlohmann::json;

/// Builds the document from nlohmann's SAX events (its public interface) and refuses a key
/// given twice. A share link of 12,000 particles is a million events: nlohmann's callback
/// parser with a set per object took six times as long as the plain parse (half a second in
/// the browser); this stays close to the plain parse.
class StrictDom {
 public:
  explicit StrictDom(json& root) : root_(root) {}

  bool null() { return value(nullptr); }
  bool boolean(bool v) { return value(v); }
  bool number_integer(json::number_integer_t v) { return value(v); }
  bool number_unsigned(json::number_unsigned_t v) { return value(v); }
  bool number_float(json::number_float_t v, const json::string_t&) { return value(v); }
  bool string(json::string_t& v) { return value(std::move(v)); }
  bool binary(json::binary_t& v) { return value(json::binary(std::move(v))); }

  bool start_object(std::size_t) {
    containers_.push_back(place(json::object()));
    levels_.emplace_back(false);
    return true;
  }
  bool key(json::string_t& k) {
    Level& level = levels_.back();
    if (level.seen(k)) {
      level.key = k;
      throw DuplicateKey(path() + ": given twice (each key at most once)");
    }
    level.key = k;
    slot_ = &(*containers_.back())[k];
    return true;
  }
  bool end_object() { return close(); }
  bool start_array(std::size_t) {
    containers_.push_back(place(json::array()));
    levels_.emplace_back(true);
    return true;
  }
  bool end_array() { return close(); }
  template <class Exception>
  bool parse_error(std::size_t, const std::string&, const Exception& e) {
    throw e;
  }

 private:
  struct Level {
    explicit Level(bool array) : is_array(array) {}

    /// Whether the object had this key already; remembers it. An object in a preset or a
    /// lesson has a handful of keys, searched in a list; a hostile one with a hundred thousand
    /// would take 10^10 comparisons that way, so past a few keys they go in a hash set.
    bool seen(const std::string& k) {
      if (few.size() < kFewKeys) {
        if (std::find(few.begin(), few.end(), k) != few.end()) return true;
        few.push_back(k);
        if (few.size() == kFewKeys) many.insert(few.begin(), few.end());
        return false;
      }
      return !many.insert(k).second;
    }

    static constexpr std::size_t kFewKeys = 16;
    bool is_array;
    long index = 0;   // the array element being read
    std::string key;  // the object's key being read
    std::vector<std::string> few;
    std::unordered_set<std::string> many;
  };

  /// Puts a value where the parser is: the root, the next array element or the key's slot.
  /// The pointer stays valid while the value is open: an array gets no next element and an
  /// object (a std::map) keeps its nodes in place.
  json* place(json v) {
    if (containers_.empty()) {
      root_ = std::move(v);
      return &root_;
    }
    json& parent = *containers_.back();
    if (parent.is_array()) {
      parent.push_back(std::move(v));
      return &parent.back();
    }
    *slot_ = std::move(v);
    return slot_;
  }

  template <class T>
  bool value(T&& v) {
    place(json(std::forward<T>(v)));
    return element_done();
  }

  bool close() {
    containers_.pop_back();
    levels_.pop_back();
    return element_done();
  }

  bool element_done() {
    if (!levels_.empty() && levels_.back().is_array) ++levels_.back().index;
    return true;
  }

  /// Where the parser is, as "particles[2].m".
  std::string path() const {
    std::string out;
    for (const Level& l : levels_)
      out += l.is_array ? "[" + std::to_string(l.index) + "]"
                        : (out.empty() ? "" : ".") + printable(l.key);
    return out;
  }

  json& root_;
  std::vector<json*> containers_;  // the open objects and arrays, outermost first
  std::vector<Level> levels_;      // the same, as the path names them
  json* slot_ = nullptr;           // the value of the object key just read
};

}  // namespace

nlohmann::json parse_strict_json(std::string_view text) {
  json root;
  StrictDom sax(root);
  json::sax_parse(text.begin(), text.end(), &sax);
  return root;
}

std::string json_syntax_error(const nlohmann::json::parse_error& e, std::string_view text) {
  // Where: the character it broke at (e.byte counts from 1), as line and column.
  const std::size_t end = std::min<std::size_t>(e.byte > 0 ? e.byte - 1 : 0, text.size());
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i < end; ++i) {
    if (text[i] == '\n')
      ++line, column = 1;
    else if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80)
      ++column;  // a character, not a UTF-8 continuation byte
  }
  // What: nlohmann's sentence after "[json.exception.parse_error.101] parse error at line 1,
  // column 5: " and "syntax error while parsing value - ".
  std::string_view what = e.what();
  if (const std::size_t at = what.find("column "); at != std::string_view::npos)
    if (const std::size_t colon = what.find(": ", at); colon != std::string_view::npos)
      what.remove_prefix(colon + 2);
  if (what.rfind("syntax error while parsing", 0) == 0)
    if (const std::size_t dash = what.find(" - "); dash != std::string_view::npos)
      what.remove_prefix(dash + 3);
  return "line " + std::to_string(line) + ", column " + std::to_string(column) + ": " +
         printable(what, 200);
}

std::string json_error_text(const nlohmann::json::exception& e) {
  std::string_view what = e.what();  // "[json.exception.out_of_range.406] number overflow ..."
  if (what.rfind("[json.exception.", 0) == 0)
    if (const std::size_t end = what.find("] "); end != std::string_view::npos)
      what.remove_prefix(end + 2);
  return printable(what, 200);
}

}  // namespace swarm
