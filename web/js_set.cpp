// swarmlab.set({...}): changes what it names, for course pages and tests. One table of keys,
// each checking its value before anything is changed, so that a bad call changes nothing and
// its message names the key and the rule. web/README.md lists the keys.

#include <emscripten.h>

#include <nlohmann/json.hpp>
#include <string>

#include "ui/presentation.h"
#include "web_app.h"

namespace {

using nlohmann::json;

struct Setter {
  const char* key;
  /// "" when the value is acceptable, else the rule it breaks.
  std::string (*check)(const json& value);
  void (*apply)(swarmlab::AppState& state, const json& value);
};

std::string boolean(const json& v) { return v.is_boolean() ? "" : "must be true or false"; }

const Setter kSetters[] = {
    {"theme",
     [](const json& v) -> std::string {
       return v == "dark" || v == "light" ? "" : "must be \"dark\" or \"light\"";
     },
     [](swarmlab::AppState& s, const json& v) {
       swarmlab::set_theme(s, v == "light" ? swarmlab::Theme::light : swarmlab::Theme::dark);
     }},
    {"presentation", boolean,
     [](swarmlab::AppState& s, const json& v) { swarmlab::set_presentation(s, v.get<bool>()); }},
    {"sound", boolean,
     [](swarmlab::AppState& s, const json& v) { swarmlab::set_sound(s, v.get<bool>()); }},
};

const Setter* setter_of(const std::string& key) {
  for (const Setter& s : kSetters)
    if (key == s.key) return &s;
  return nullptr;
}

std::string known_keys() {
  std::string keys;
  for (const Setter& s : kSetters) keys += std::string(keys.empty() ? "" : ", ") + s.key;
  return keys;
}

std::string set_error;  // valid until the next call

std::string set_from_json(swarmlab::AppState& state, const std::string& text) {
  const json changes = json::parse(text, nullptr, false);
  if (!changes.is_object()) return "swarmlab.set: expects an object such as {theme: \"light\"}";
  for (const auto& [key, value] : changes.items()) {
    const Setter* setter = setter_of(key);
    if (!setter) return "swarmlab.set: unknown key \"" + key + "\" (known: " + known_keys() + ")";
    if (const std::string rule = setter->check(value); !rule.empty())
      return "swarmlab.set: " + key + ": " + rule;
  }
  // In the table's order, not the object's: {presentation: true, theme: "dark"} is the
  // dark theme in presentation mode whichever key came first.
  for (const Setter& s : kSetters)
    if (changes.contains(s.key)) s.apply(state, changes[s.key]);
  return {};
}

}  // namespace

extern "C" {

/// Applies the JSON object of changes; "" on success, else the message naming the key (and
/// nothing is changed).
EMSCRIPTEN_KEEPALIVE const char* swarmlab_set(const char* changes) {
  swarmlab::App* app = swarmlab::web_app();
  set_error = app ? set_from_json(app->state(), changes) : "the app has not started";
  return set_error.c_str();
}

}  // extern "C"
