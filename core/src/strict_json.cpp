#include "swarm/strict_json.h"

#include <algorithm>
#include <string>
#include <vector>

#include "swarm/printable_text.h"

namespace swarm {
namespace {

using json = nlohmann::json;

/// nlohmann's own DOM builder, watched for repeated keys. A share link of 12,000 particles is a
/// million events: nlohmann's callback parser and a std::set per object took six times as long
/// as the plain parse (half a second in the browser); this stays close to the plain parse.
class StrictDom {
 public:
  explicit StrictDom(json& root) : dom_(root) {}

  bool null() { return value_done(dom_.null()); }
  bool boolean(bool v) { return value_done(dom_.boolean(v)); }
  bool number_integer(json::number_integer_t v) { return value_done(dom_.number_integer(v)); }
  bool number_unsigned(json::number_unsigned_t v) { return value_done(dom_.number_unsigned(v)); }
  bool number_float(json::number_float_t v, const json::string_t& s) {
    return value_done(dom_.number_float(v, s));
  }
  bool string(json::string_t& v) { return value_done(dom_.string(v)); }
  bool binary(json::binary_t& v) { return value_done(dom_.binary(v)); }

  bool start_object(std::size_t n) {
    levels_.push_back({false, 0, {}});
    return dom_.start_object(n);
  }
  bool key(json::string_t& k) {
    // An object in a preset or a lesson has a handful of keys: a linear search beats a set.
    std::vector<std::string>& keys = levels_.back().keys;
    if (std::find(keys.begin(), keys.end(), k) != keys.end()) {
      keys.push_back(k);
      throw DuplicateKey(path() + ": given twice (each key at most once)");
    }
    keys.push_back(k);
    return dom_.key(k);
  }
  bool end_object() {
    levels_.pop_back();
    return value_done(dom_.end_object());
  }
  bool start_array(std::size_t n) {
    levels_.push_back({true, 0, {}});
    return dom_.start_array(n);
  }
  bool end_array() {
    levels_.pop_back();
    return value_done(dom_.end_array());
  }
  template <class Exception>
  bool parse_error(std::size_t at, const std::string& token, const Exception& e) {
    return dom_.parse_error(at, token, e);
  }

 private:
  struct Level {
    bool is_array;
    long index;                     // the array element being read
    std::vector<std::string> keys;  // the object's keys so far; the last is being read
  };

  bool value_done(bool ok) {
    if (!levels_.empty() && levels_.back().is_array) ++levels_.back().index;
    return ok;
  }

  /// Where the parser is, as "particles[2].m".
  std::string path() const {
    std::string out;
    for (const Level& l : levels_)
      out += l.is_array ? "[" + std::to_string(l.index) + "]"
                        : (out.empty() ? "" : ".") + printable(l.keys.back());
    return out;
  }

  nlohmann::detail::json_sax_dom_parser<json> dom_;
  std::vector<Level> levels_;
};

}  // namespace

nlohmann::json parse_strict_json(std::string_view text) {
  json root;
  StrictDom sax(root);
  json::sax_parse(text.begin(), text.end(), &sax);
  return root;
}

}  // namespace swarm
