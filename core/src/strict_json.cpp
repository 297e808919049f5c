#include "swarm/strict_json.h"

#include <set>
#include <string>
#include <vector>

#include "swarm/printable_text.h"

namespace swarm {

nlohmann::json parse_strict_json(std::string_view text) {
  using json = nlohmann::json;
  struct Level {
    bool is_array = false;
    long index = 0;
    std::string key;
    std::set<std::string> keys;
  };
  std::vector<Level> levels;
  auto path = [&levels]() {
    std::string out;
    for (const Level& l : levels)
      out += l.is_array ? "[" + std::to_string(l.index) + "]"
                        : (out.empty() ? "" : ".") + printable(l.key);
    return out;
  };
  auto value_done = [&levels]() {
    if (!levels.empty() && levels.back().is_array) ++levels.back().index;
  };
  const json::parser_callback_t on_event = [&](int, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
        levels.push_back({false, 0, {}, {}});
        break;
      case json::parse_event_t::array_start:
        levels.push_back({true, 0, {}, {}});
        break;
      case json::parse_event_t::key: {
        Level& l = levels.back();
        l.key = parsed.get<std::string>();
        if (!l.keys.insert(l.key).second)
          throw DuplicateKey(path() + ": given twice (each key at most once)");
        break;
      }
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        levels.pop_back();
        value_done();
        break;
      case json::parse_event_t::value:
        value_done();
        break;
    }
    return true;
  };
  return json::parse(text.begin(), text.end(), on_event);
}

}  // namespace swarm
