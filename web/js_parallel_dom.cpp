// The C side of web/parallel_dom.js: the items the front end drew in the last frame, as JSON,
// and what the page's mirrored elements ask of them (app/ui/parallel_dom/parallel_dom.h).

#include <emscripten.h>

#include <string>

#include "ui/parallel_dom/items_json.h"
#include "ui/parallel_dom/parallel_dom.h"
#include "web_app.h"

namespace {

std::string items_text;  // valid until the next call

}  // namespace

extern "C" {

/// The items of the last frame as JSON (app/ui/parallel_dom/items_json.h).
EMSCRIPTEN_KEEPALIVE const char* swarmlab_dom_items() {
  swarmlab::App* app = swarmlab::web_app();
  items_text = swarmlab::items_json(swarmlab::parallel_dom(), app && app->state().layout.touch);
  return items_text.c_str();
}

/// Presses the item (a click, Enter or Space on its element).
EMSCRIPTEN_KEEPALIVE void swarmlab_dom_activate(unsigned id) { swarmlab::parallel_dom().request_activate(id); }

/// Puts ImGui's keyboard focus on the item and scrolls it into view; ring: with its focus ring
/// (the page's last input was a key).
EMSCRIPTEN_KEEPALIVE void swarmlab_dom_focus(unsigned id, int ring) {
  swarmlab::parallel_dom().request_focus(id, ring != 0);
}

/// Types text into the field and commits it, with Enter when `enter` is 1.
EMSCRIPTEN_KEEPALIVE void swarmlab_dom_type(unsigned id, const char* text, int enter) {
  swarmlab::parallel_dom().request_text(id, text ? text : "", enter != 0);
}

}  // extern "C"
