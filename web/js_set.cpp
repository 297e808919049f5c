// swarmlab.set({...}): changes what it names, for course pages and tests. One table of keys,
// each with its check and its change; a feature adds its row. Every key is checked before any
// is changed, so a bad call changes nothing; the changes are made in the table's order.

#include <emscripten.h>

#include <nlohmann/json.hpp>
#include <cstdint>
#include <string>

#include "i18n/language.h"
#include "ui/classroom/embedding.h"
#include "ui/classroom/presentation.h"
#include "web_app.h"

namespace {

using nlohmann::json;
using swarmlab::AppState;

struct Key {
  const char* name;
  std::string rule;                  ///< what a good value is, for the error message
  bool (*valid)(const AppState&, const json&);
  void (*apply)(AppState&, const json&);
};

bool number_in(const json& v, double lo, double hi) {
  return v.is_number() && v.get<double>() >= lo && v.get<double>() <= hi;
}

/// Whether v is an integer from 0 to n - 1, compared before any conversion (JSON's integers
/// are 64 bits, signed or not; a size_t in wasm is 32).
bool index_below(const json& v, std::size_t n) {
  if (v.is_number_unsigned()) return v.get<std::uint64_t>() < n;
  return v.is_number_integer() && v.get<std::int64_t>() >= 0 && std::uint64_t(v.get<std::int64_t>()) < n;
}

const Key kKeys[] = {
    {"playing", "must be true or false", [](const AppState&, const json& v) { return v.is_boolean(); },
     [](AppState& s, const json& v) { s.playing = v.get<bool>(); }},
    {"speed", "must be a number in [0.001, 10000] (simulated time per second)",
     [](const AppState&, const json& v) { return number_in(v, 1e-3, 1e4); },
     [](AppState& s, const json& v) { s.speed = v.get<double>(); }},
    {"layout", "must be \"auto\", \"wide\" or \"compact\"",
     [](const AppState&, const json& v) {
       swarmlab::LayoutMode m;
       return v.is_string() && swarmlab::parse_layout_mode(v.get<std::string>(), m);
     },
     [](AppState& s, const json& v) { swarmlab::parse_layout_mode(v.get<std::string>(), s.layout.mode); }},
    {"ui_scale", "must be a number in [0.75, 2.5]",
     [](const AppState&, const json& v) {
       return number_in(v, swarmlab::Layout::kMinUiScale, swarmlab::Layout::kMaxUiScale);
     },
     [](AppState& s, const json& v) { s.layout.pending_ui_scale = v.get<float>(); }},
    {"selected", "must be a particle index (an integer from 0 to N - 1) or null",
     [](const AppState& s, const json& v) {
       return v.is_null() || index_below(v, s.run->system().particles.size());
     },
     [](AppState& s, const json& v) {
       if (v.is_null()) s.selected.reset();
       else s.selected = std::size_t(v.get<std::uint64_t>());
       s.update_followed();
     }},
    // The projector and the classroom (app/ui/classroom/presentation.h). Presentation comes after the
    // theme, so {presentation: true, theme: "dark"} is presentation mode, light.
    // Applied between frames (a new font atlas); state().language follows on the next frame.
    {"language", "must be a language code: " + swarmlab::language_codes("\""),
     [](const AppState&, const json& v) {
       return v.is_string() && swarmlab::find_language(v.get<std::string>()) != nullptr;
     },
     [](AppState& s, const json& v) { s.language.pending = v.get<std::string>(); }},
    {"theme", "must be \"dark\" or \"light\"",
     [](const AppState&, const json& v) { return v == "dark" || v == "light"; },
     [](AppState& s, const json& v) {
       swarmlab::set_theme(s, v == "light" ? swarmlab::Theme::light : swarmlab::Theme::dark);
     }},
    {"presentation", "must be true or false",
     [](const AppState&, const json& v) { return v.is_boolean(); },
     [](AppState& s, const json& v) { swarmlab::set_presentation(s, v.get<bool>()); }},
    {"sound", "must be true or false", [](const AppState&, const json& v) { return v.is_boolean(); },
     [](AppState& s, const json& v) { swarmlab::set_sound(s, v.get<bool>()); }},
    // Inside a course page (app/ui/classroom/embedding.h); embed_bridge.js sets it for ?embed.
    {"embed", "must be true or false", [](const AppState&, const json& v) { return v.is_boolean(); },
     [](AppState& s, const json& v) { swarmlab::set_embedded(s, v.get<bool>()); }},
};

std::string set_error;

std::string apply_settings(AppState& state, const std::string& text) {
  const json j = json::parse(text, nullptr, false);
  if (!j.is_object()) return "swarmlab.set(): expects an object such as {playing: false}";
  for (const auto& [name, value] : j.items()) {
    const Key* key = nullptr;
    for (const Key& k : kKeys)
      if (name == k.name) key = &k;
    if (!key) {
      std::string known;
      for (const Key& k : kKeys) known += std::string(known.empty() ? "" : ", ") + k.name;
      return "swarmlab.set(): unknown key \"" + name + "\" (known: " + known + ")";
    }
    if (!key->valid(state, value))
      return "swarmlab.set(): " + name + ": " + key->rule + ", not " + value.dump();
  }
  // In the table's order, not the object's.
  for (const Key& k : kKeys)
    if (j.contains(k.name)) k.apply(state, j[k.name]);
  return {};
}

}  // namespace

extern "C" {

/// Applies a JSON object of settings; "" on success, else the message naming the bad key.
EMSCRIPTEN_KEEPALIVE const char* swarmlab_set(const char* settings) {
  swarmlab::App* app = swarmlab::web_app();
  set_error = app ? apply_settings(app->state(), settings) : "the app has not started";
  return set_error.c_str();
}

}  // extern "C"
