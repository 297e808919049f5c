// The student's lesson progress in the browser: one JSON text in localStorage, kept between
// visits to the page (and lost only when the browser's site data is cleared).

#include <emscripten.h>

#include <cstdlib>

#include "web_app.h"

namespace swarmlab {
namespace {

// (EM_JS bodies: double quotes and no backslashes, which the preprocessor and the metadata
// would mangle.) localStorage may be missing or refuse (private windows, a full quota): progress then lasts
// the visit only.
// clang-format off
EM_JS(char*, progress_load, (), {
  var text = "";
  try { text = window.localStorage.getItem("swarmlab.progress") || ""; } catch (e) { text = ""; }
  var size = lengthBytesUTF8(text) + 1;
  var pointer = _malloc(size);
  stringToUTF8(text, pointer, size);
  return pointer;
});
EM_JS(void, progress_save, (const char* text), {
  try { window.localStorage.setItem("swarmlab.progress", UTF8ToString(text)); } catch (e) {}
});
// clang-format on

class WebProgressStore final : public ProgressStore {
 public:
  std::string load() override {
    char* text = progress_load();
    std::string out = text;
    std::free(text);
    return out;
  }
  void save(const std::string& json) override { progress_save(json.c_str()); }
};

}  // namespace

std::unique_ptr<ProgressStore> make_web_progress_store() {
  return std::make_unique<WebProgressStore>();
}

}  // namespace swarmlab
