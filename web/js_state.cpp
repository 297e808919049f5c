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
  // The instruments: P and T as the read-outs show them (null without a container or before
  // the first sample; T also before the first wall hit), the stopwatch, the measured period.
  const swarmlab::Instruments& in = s.instruments;
  const bool wall = s.preset.container_radius && in.wall.intervals > 0;
  j["P"] = wall ? nlohmann::json(in.wall.mean.P) : nlohmann::json(nullptr);
  j["T"] = wall && in.wall.mean.hits > 0 ? nlohmann::json(in.wall.mean.T) : nlohmann::json(nullptr);
  j["stopwatch"] = {{"running", in.stopwatch.running()}, {"elapsed", in.stopwatch.elapsed()}};
  const auto period = in.track ? in.track->meter.period() : std::nullopt;
  j["measured_period"] = period ? nlohmann::json(*period) : nlohmann::json(nullptr);
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
