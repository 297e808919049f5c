// swarmlab.seek(t) and swarmlab.positions(): the run moved in time and read particle by
// particle, for course pages and tests (web/README.md). A seek is carried out a frame's budget
// at a time (time_controls.h): swarmlab_api.js starts it and follows it to its end.

#include <emscripten.h>

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

#include "ui/time/time_controls.h"
#include "web_app.h"

namespace {

constexpr std::size_t kMaxPositions = 10000;
std::string positions_text, seek_text;  // valid until the next call

}  // namespace

extern "C" {

/// Starts moving the run to time t: {"id": the seek's id} (it may have ended at once; see
/// swarmlab_seek_poll), or {"error": why t is refused}, in which case nothing changes.
EMSCRIPTEN_KEEPALIVE const char* swarmlab_seek_start(double t) {
  nlohmann::json answer;
  if (swarmlab::App* app = swarmlab::web_app()) {
    const std::string refusal = swarmlab::seek_refusal(app->state(), t);
    if (refusal.empty())
      answer["id"] = swarmlab::seek_in_frames(app->state(), t);
    else
      answer["error"] = refusal;
  } else {
    answer["error"] = "the app has not started";
  }
  seek_text = answer.dump();
  return seek_text.c_str();
}

/// The seeks that ended since the last call, [{id, reached}], the seek under way {id, progress}
/// or null, and the time now: {"ended": [...], "running": ..., "t": ...}.
EMSCRIPTEN_KEEPALIVE const char* swarmlab_seek_poll() {
  nlohmann::json answer = {{"ended", nlohmann::json::array()}, {"running", nullptr}, {"t", 0.0}};
  if (swarmlab::App* app = swarmlab::web_app()) {
    swarmlab::AppState& s = app->state();
    for (const swarmlab::TravelEnd& end : s.travel_ends)
      answer["ended"].push_back({{"id", end.id},
                                 {"t", end.t},
                                 {"reached", end.reached}});
    s.travel_ends.clear();
    if (s.travel.kind == swarmlab::TimeTravel::Kind::to_time)
      answer["running"] = {{"id", s.travel.id}, {"progress", s.travel.progress(s.run->step())}};
    answer["t"] = s.run->time();
  }
  seek_text = answer.dump();
  return seek_text.c_str();
}

/// The lab positions of the first 10,000 particles as JSON, [[x, y, z], ...], every digit
/// kept (%.17g), so that two calls can be compared bit for bit.
EMSCRIPTEN_KEEPALIVE const char* swarmlab_positions() {
  positions_text = "[";
  if (swarmlab::App* app = swarmlab::web_app()) {
    const swarm::System& s = app->state().run->system();
    const std::size_t n = std::min(s.particles.size(), kMaxPositions);
    char buf[96];
    for (std::size_t i = 0; i < n; ++i) {
      const swarm::Vec3& r = s.particles[i].r;
      std::snprintf(buf, sizeof buf, "%s[%.17g,%.17g,%.17g]", i ? "," : "", r.x(), r.y(), r.z());
      positions_text += buf;
    }
  }
  positions_text += "]";
  return positions_text.c_str();
}

}  // extern "C"
