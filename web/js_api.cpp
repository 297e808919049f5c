// The C side of window.swarmlab (web/swarmlab_api.js calls these through ccall), and the
// opening and downloading of presets that the API and the scenario panel's buttons share.

#include <emscripten.h>

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "i18n/translator.h"
#include "storage_controls.h"
#include "ui/platform/save_dialog.h"
#include "web_app.h"
#include "web_preset_store.h"

namespace swarmlab {

std::string open_preset_json(AppState& state, const std::string& json, const std::string& source,
                             const std::string& location) {
  std::string error = state.open_json(json, location);
  if (!error.empty()) {
    // The CLI says "error: FILE: field: problem"; here the source takes the file's place.
    error = source + ": " + error;
    state.status = error;
    state.status_is_error = true;
    return error;
  }
  char text[600];
  // A file keeps its name; the page's own sources are words (tr_noop: "share link").
  tr_noop("share link");
  std::snprintf(text, sizeof text, tr("Opened %s"), tr(source.c_str()));
  state.status = text;
  state.status_is_error = false;
  return {};
}

std::string download_preset(AppState& state) {
  const std::string name = download_file_name(state.location);
  const std::string error = state.store->save(name, swarm::preset_to_json(state.preset));
  char text[600];
  std::snprintf(text, sizeof text, tr("Downloaded %s (see the browser's downloads)"), name.c_str());
  state.status = error.empty() ? std::string(text) : error;
  state.status_is_error = !error.empty();
  return name;
}

}  // namespace swarmlab

namespace {

// The strings handed to JavaScript stay valid until the next call of the same function.
std::string preset_text, open_error, download_name, shipped_text, rect_text, csv_name;

}  // namespace

extern "C" {

/// The simulated time of the running preset (the primary method's clock).
EMSCRIPTEN_KEEPALIVE double swarmlab_time() {
  swarmlab::App* app = swarmlab::web_app();
  return app ? app->state().run->time() : 0.0;
}

/// The running preset (every edit included) as JSON; indent < 0 gives one compact line.
EMSCRIPTEN_KEEPALIVE const char* swarmlab_preset(int indent) {
  swarmlab::App* app = swarmlab::web_app();
  preset_text = app ? swarm::preset_to_json(app->state().preset, indent) : std::string();
  return preset_text.c_str();
}

/// Opens a preset from JSON text of `bytes` bytes; "" on success, else the message also shown
/// in the panel. The caller passes json in a malloc'd buffer, not on the wasm stack, and has
/// already refused text over the size limit (web/swarmlab_api.js). The length comes with it,
/// so that a NUL byte in a file is refused by the preset's rule, not taken for its end.
EMSCRIPTEN_KEEPALIVE const char* swarmlab_open_json(const char* json, int bytes, const char* source,
                                                    const char* location) {
  swarmlab::App* app = swarmlab::web_app();
  open_error = app ? swarmlab::open_preset_json(app->state(), std::string(json, std::size_t(bytes)),
                                                source, location)
                   : std::string("the app has not started");
  return open_error.c_str();
}

/// Sets the scenario panel's status line (the result of Copy link, a share link that cannot
/// be decoded).
EMSCRIPTEN_KEEPALIVE void swarmlab_set_status(const char* text, int is_error) {
  if (swarmlab::App* app = swarmlab::web_app()) {
    app->state().status = text;
    app->state().status_is_error = is_error != 0;
  }
}

/// The scenario list's shipped presets, one "file name<TAB>preset name" line each.
EMSCRIPTEN_KEEPALIVE const char* swarmlab_shipped() {
  shipped_text.clear();
  if (swarmlab::App* app = swarmlab::web_app())
    for (const swarmlab::ShippedPreset& s : app->state().shipped)
      shipped_text += s.id + "\t" + s.preset.name + "\n";
  return shipped_text.c_str();
}

/// What the Download preset button does; returns the file name.
EMSCRIPTEN_KEEPALIVE const char* swarmlab_download() {
  swarmlab::App* app = swarmlab::web_app();
  download_name = app ? swarmlab::download_preset(app->state()) : std::string();
  return download_name.c_str();
}

/// The number of particles, the range of every particle index the page passes.
EMSCRIPTEN_KEEPALIVE double swarmlab_particle_count() {
  swarmlab::App* app = swarmlab::web_app();
  return app ? double(app->state().run->system().particles.size()) : 0.0;
}

/// Selects particle `index` (-1: none), as a click on it does. Returns -1 on success, and the
/// number of particles when there is no such particle. The index is compared as a double
/// before it becomes a size_t (32 bits in wasm), so 2^32 + 2 cannot wrap to particle 2.
EMSCRIPTEN_KEEPALIVE double swarmlab_select(double index) {
  swarmlab::App* app = swarmlab::web_app();
  if (!app) return 0;
  const double count = swarmlab_particle_count();
  if (index == -1) app->state().select_particle(std::nullopt);
  else if (index >= 0 && index < count && index == std::floor(index))
    app->state().select_particle(std::size_t(index));
  else return count;
  return -1;
}

/// The stopwatch's buttons: 0 start, 1 stop, 2 lap, 3 reset, at the simulated clock's reading.
EMSCRIPTEN_KEEPALIVE void swarmlab_stopwatch(int action) {
  swarmlab::App* app = swarmlab::web_app();
  if (!app) return;
  swarm::Stopwatch& w = app->state().instruments.stopwatch;
  const double t = app->state().run->time();
  if (action == 0) w.start(t);
  if (action == 1) w.stop(t);
  if (action == 2) w.lap(t);
  if (action == 3) w.reset();
}

/// swarmlab.exportCsv(): the samples as CSV (the CLI's columns) as a download; its file name.
EMSCRIPTEN_KEEPALIVE const char* swarmlab_export_csv() {
  swarmlab::App* app = swarmlab::web_app();
  csv_name = app ? swarmlab::request_samples_csv(app->state()) : std::string();
  return csv_name.c_str();
}

/// Where the scenario panel's button `label` was drawn: "x y width height" in CSS pixels, or
/// "" when the panel is closed (for tests that click it).
EMSCRIPTEN_KEEPALIVE const char* swarmlab_button_rect(const char* label) {
  rect_text = swarmlab::storage_button_rect(label);
  return rect_text.c_str();
}

}  // extern "C"
