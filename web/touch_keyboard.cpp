// The C side of web/touch_keyboard.js: the number field being typed into with fingers, and
// the text typed for it on the on-screen keyboard.

#include <emscripten.h>

#include <cstdio>
#include <string>

#include "web_app.h"

namespace {

std::string field_text;  // valid until the next call

}  // namespace

extern "C" {

/// "x y width height<TAB>text" of the number field being edited with fingers (CSS pixels),
/// or "" when none is.
EMSCRIPTEN_KEEPALIVE const char* swarmlab_text_field() {
  swarmlab::App* app = swarmlab::web_app();
  field_text.clear();
  if (!app || !app->state().layout.touch) return "";
  const swarmlab::Layout::TextField& f = app->state().layout.text_field;
  if (!f.active) return "";
  char rect[96];
  std::snprintf(rect, sizeof rect, "%.1f %.1f %.1f %.1f\t", f.rect.x, f.rect.y, f.rect.width,
                f.rect.height);
  field_text = rect + f.text;
  return field_text.c_str();
}

/// Commits text to the field being edited, on the next frame (as Enter would).
EMSCRIPTEN_KEEPALIVE void swarmlab_type_text(const char* text) {
  if (swarmlab::App* app = swarmlab::web_app()) app->state().layout.typed_text = text;
}

}  // extern "C"
