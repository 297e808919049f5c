// The student's lesson progress in the browser: one JSON text in localStorage, kept between
// visits to the page (and lost only when the browser's site data is cleared). A refusal is
// reported, never swallowed: the lesson session says it once (progress_record.h).

#include <emscripten.h>

#include <cstdlib>

#include "web_app.h"

namespace swarmlab {
namespace {

// (EM_JS bodies: double quotes and no backslashes, which the preprocessor and the metadata
// would mangle.) localStorage may be missing or refuse: a private window, a full quota, or
// storage blocked by a school's policy, where even reading window.localStorage throws.
// clang-format off
EM_JS(char*, progress_load, (), {
  var text = "";
  try { text = window.localStorage.getItem("swarmlab.progress") || ""; } catch (e) { text = ""; }
  var size = lengthBytesUTF8(text) + 1;
  var pointer = _malloc(size);
  stringToUTF8(text, pointer, size);
  return pointer;
});
// The error's name ("QuotaExceededError", "SecurityError"), "" when saved.
EM_JS(char*, progress_save, (const char* text), {
  var error = "";
  try { window.localStorage.setItem("swarmlab.progress", UTF8ToString(text)); }
  catch (e) { error = (e && e.name) || "Error"; }
  var size = lengthBytesUTF8(error) + 1;
  var pointer = _malloc(size);
  stringToUTF8(error, pointer, size);
  return pointer;
});
// The record under swarmlab.progress.unreadable-<ISO time> (never over another): the key, or
// "" when it could not be written.
EM_JS(char*, progress_set_aside, (const char* text), {
  var key = "";
  try {
    var storage = window.localStorage;
    var base = "swarmlab.progress.unreadable-" + new Date().toISOString();
    key = base;
    for (var n = 2; storage.getItem(key) !== null; ++n) key = base + "-" + n;
    storage.setItem(key, UTF8ToString(text));
  } catch (e) { key = ""; }
  var size = lengthBytesUTF8(key) + 1;
  var pointer = _malloc(size);
  stringToUTF8(key, pointer, size);
  return pointer;
});
// clang-format on

std::string taken(char* text) {
  std::string out = text;
  std::free(text);
  return out;
}

class WebProgressStore final : public ProgressStore {
 public:
  std::string load() override { return taken(progress_load()); }
  std::string save(const std::string& json) override { return taken(progress_save(json.c_str())); }
  std::string set_aside(const std::string& text) override {
    return taken(progress_set_aside(text.c_str()));
  }
};

}  // namespace

std::unique_ptr<ProgressStore> make_web_progress_store() {
  return std::make_unique<WebProgressStore>();
}

}  // namespace swarmlab
