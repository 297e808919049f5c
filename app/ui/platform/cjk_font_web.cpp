#include <emscripten.h>

#include <string>

#include "files/text_file.h"
#include "ui/platform/cjk_font.h"

namespace {

bool requested = false, arrived = false;
std::string bytes;

}  // namespace

// Called by the page when the font is in the in-memory file system.
extern "C" EMSCRIPTEN_KEEPALIVE void swarmlab_cjk_font_ready() { arrived = true; }

namespace swarmlab {
namespace {

// (EM_JS bodies: double quotes and no backslashes.) The service worker, when there is one,
// keeps the fetched font for offline visits. The page names the font as the build published
// it, with its content's hash (window.swarmlabFiles, web/publish.py).
// clang-format off
EM_JS(void, fetch_cjk_font, (), {
  var name = "fonts/noto-sans-sc-subset.otf";
  fetch((window.swarmlabFiles && window.swarmlabFiles[name]) || name)
    .then(function(r) { if (!r.ok) throw new Error("HTTP " + r.status); return r.arrayBuffer(); })
    .then(function(b) { FS.writeFile("/cjk-font.otf", new Uint8Array(b)); _swarmlab_cjk_font_ready(); _swarmlab_wake(); })
    .catch(function(e) { console.warn("Swarm Lab: the Chinese font did not load: " + e); _swarmlab_cjk_font_ready(); _swarmlab_wake(); });
});
// clang-format on

}  // namespace

std::string_view cjk_font() { return bytes; }

void request_cjk_font() {
  if (requested) return;
  requested = true;
  fetch_cjk_font();
}

bool cjk_font_arrived() {
  if (!arrived) return false;
  arrived = false;
  std::string error;
  bytes = read_text_file("/cjk-font.otf", error);
  if (!error.empty()) requested = false;  // failed: the next choice of Chinese tries again
  return true;
}

}  // namespace swarmlab
