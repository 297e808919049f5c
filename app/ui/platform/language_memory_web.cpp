#include <emscripten.h>

#include <cstdlib>

#include "i18n/language.h"
#include "ui/platform/language_memory.h"

namespace swarmlab {
namespace {

// (EM_JS bodies: double quotes and no backslashes.) localStorage may be missing or refuse (a
// private window, storage blocked by a school's policy): the language then lasts this visit.
// clang-format off
EM_JS(void, store_language, (const char* code), {
  var text = UTF8ToString(code);
  window.swarmlabLanguage = text;  // the page's own texts and shared links follow
  document.documentElement.lang = window.swarmlabDocumentLanguage(text);
  try { window.localStorage.setItem("swarmlab.language", text); } catch (e) {}
});

EM_JS(char*, page_language, (), {
  var code = typeof window.swarmlabLanguage === "string" ? window.swarmlabLanguage : "";
  var size = lengthBytesUTF8(code) + 1;
  var pointer = _malloc(size);
  stringToUTF8(code, pointer, size);
  return pointer;
});
// clang-format on

std::string taken(char* text) {
  std::string s(text);
  std::free(text);
  return s;
}

}  // namespace

void remember_language(const std::string& code) { store_language(code.c_str()); }

std::string startup_language() {
  const std::string code = taken(page_language());
  return find_language(code) ? code : source_language().code;
}

}  // namespace swarmlab
