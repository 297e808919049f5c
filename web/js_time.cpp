// swarmlab.seek(t) and swarmlab.positions(): the run moved in time and read particle by
// particle, for course pages and tests (web/README.md).

#include <emscripten.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "ui/time/time_controls.h"
#include "web_app.h"

namespace {

constexpr std::size_t kMaxPositions = 10000;
std::string positions_text;  // valid until the next call

}  // namespace

extern "C" {

/// Moves the run to time t, back or forward, at once (swarm::Timeline); returns the time
/// reached (t rounded to a step, within [0, the run's end]).
EMSCRIPTEN_KEEPALIVE double swarmlab_seek(double t) {
  swarmlab::App* app = swarmlab::web_app();
  return app ? swarmlab::seek_now(app->state(), t) : 0.0;
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
