// swarmlab.state(): what the app shows and runs, as one JSON object, for course pages and
// tests. Each feature adds its own fields here (web/README.md lists them).

#include <emscripten.h>

#include <nlohmann/json.hpp>
#include <string>

#include "web_app.h"

namespace {

std::string state_text;  // valid until the next call

nlohmann::json app_state_json(swarmlab::App& app) {
  const swarmlab::AppState& s = app.state();
  nlohmann::json j;
  j["name"] = s.preset.name;
  j["edited"] = s.modified;
  j["playing"] = s.playing;
  j["t"] = s.run->time();
  j["speed"] = s.speed;
  j["selected"] = s.selected ? nlohmann::json(*s.selected) : nlohmann::json(nullptr);
  // Time (web/js_time.cpp): the furthest time computed, and a fast-forward under way.
  j["t_reached"] = double(s.run->timeline().reached()) * s.preset.dt;
  j["fast_forward"] = s.travel.active() && s.travel.kind != swarmlab::TimeTravel::Kind::seek
                          ? nlohmann::json{{"progress", s.travel.progress(s.run->step())}}
                          : nlohmann::json(nullptr);
  return j;
}

}  // namespace

extern "C" {

/// The app's state as compact JSON ("{}" before main() has made the app).
EMSCRIPTEN_KEEPALIVE const char* swarmlab_state() {
  swarmlab::App* app = swarmlab::web_app();
  state_text = app ? app_state_json(*app).dump() : "{}";
  return state_text.c_str();
}

}  // extern "C"
