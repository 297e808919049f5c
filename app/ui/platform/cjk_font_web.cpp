#include <emscripten.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "files/sha256.h"
#include "ui/platform/cjk_font.h"
#include "ui/platform/font_file_check.h"

// The font is fetched once, and once more after a pause when that fails (a 404, a refused
// connection, a cut or foreign answer that the atlas refused); then the page says that Chinese
// cannot be shown and offers a retry (web/shell.html, Module.onCjkFontMissing), which starts
// the same two tries again. Never more: a missing font was once fetched 44 times in 12 s.

namespace swarmlab {
namespace {

constexpr int kTries = 2;
constexpr int kSecondTryDelayMs = 3000;

enum class Fetch { idle, on_the_way, here, given_up };
Fetch fetch = Fetch::idle;
int tries = 0;         // of the two, since the first request or the last retry
bool missing = false;  // gave up, and no bytes arrived since
std::string bytes;

// What the page handed over since the last news.
bool delivered = false, fetched = false;
std::string received;
CjkFontNews pending_news = CjkFontNews::none;  // from refuse_cjk_font, told at the next news

// (EM_JS bodies: double quotes and no backslashes.) The page names the font as the build
// published it, with the first 8 hex digits of its content's SHA-256 (window.swarmlabFiles,
// web/publish.py). The body is read up to max_bytes and no further and copied into the wasm
// heap for swarmlab_cjk_font_ready (a null pointer: nothing came, and the console says why),
// whose digest the app checks itself: the browser's crypto.subtle exists only in a secure
// context, not on a class server's plain http address. A try after a failure goes past the
// browser's HTTP cache.
// clang-format off
EM_JS(void, fetch_cjk_font, (int delay_ms, int reload, int max_bytes), {
  var name = "fonts/noto-sans-sc-subset.otf";
  var url = (window.swarmlabFiles && window.swarmlabFiles[name]) || name;
  function body(r) {
    if (!r.ok) throw new Error("HTTP " + r.status);
    var announced = Number(r.headers.get("Content-Length") || 0);
    if (announced > max_bytes) throw new Error(announced + " bytes, more than " + max_bytes);
    if (!r.body) return r.arrayBuffer().then(function(b) { return new Uint8Array(b); });
    var reader = r.body.getReader(), parts = [], size = 0;
    function pump() {
      return reader.read().then(function(part) {
        if (part.done) {
          var all = new Uint8Array(size), at = 0;
          parts.forEach(function(p) { all.set(p, at); at += p.length; });
          return all;
        }
        size += part.value.length;
        if (size > max_bytes) { reader.cancel(); throw new Error("more than " + max_bytes + " bytes"); }
        parts.push(part.value);
        return pump();
      });
    }
    return pump();
  }
  function hand_over(b, why) {
    var pointer = 0;
    if (b) {
      pointer = _malloc(Math.max(b.length, 1));
      if (pointer) HEAPU8.set(b, pointer); else why = "no memory for " + b.length + " bytes";
    }
    if (!pointer) console.warn("Swarm Lab: the Chinese font did not load (" + url + "): " + why);
    _swarmlab_cjk_font_ready(pointer, b ? b.length : 0);
    _swarmlab_wake();
  }
  setTimeout(function() {
    fetch(url, reload ? { cache: "reload" } : {}).then(body)
      .then(function(b) { hand_over(b, ""); }, function(e) { hand_over(null, String(e)); });
  }, delay_ms);
});

// Refused bytes are dropped from the service worker's caches too, or every later visit and
// every retry would get them again (the worker answers from its cache first).
EM_JS(void, forget_cached_cjk_font, (), {
  try {
    if (!window.caches) return;
    var name = "fonts/noto-sans-sc-subset.otf";
    var url = new URL((window.swarmlabFiles && window.swarmlabFiles[name]) || name, document.baseURI).href;
    caches.keys().then(function(keys) {
      keys.forEach(function(key) {
        if (key.indexOf("swarmlab-") === 0) caches.open(key).then(function(c) { return c.delete(url); });
      });
    }).catch(function() {});
  } catch (e) {}
});

// The first 8 hex digits of the SHA-256 that the font's published name carries, in a malloc'd
// string ("" for a name without them, as in a build that does not publish).
EM_JS(char*, published_cjk_font_digest, (), {
  var name = "fonts/noto-sans-sc-subset.otf";
  var parts = ((window.swarmlabFiles && window.swarmlabFiles[name]) || name).split("/").pop().split(".");
  var want = parts.length > 2 && /^[0-9a-f]{8}$/.test(parts[parts.length - 2]) ? parts[parts.length - 2] : "";
  var pointer = _malloc(want.length + 1);
  if (pointer) stringToUTF8(want, pointer, want.length + 1);
  return pointer;
});

EM_JS(void, tell_page_cjk_font_missing, (), {
  if (Module.onCjkFontMissing)
    Module.onCjkFontMissing(function() { _swarmlab_retry_cjk_font(); _swarmlab_wake(); });
});
EM_JS(void, tell_page_cjk_font_here, (), { if (Module.onCjkFontHere) Module.onCjkFontHere(); });
// clang-format on

void start_try() {
  fetch = Fetch::on_the_way;
  const bool after_a_failure = tries > 0 || missing;
  fetch_cjk_font(tries == 0 ? 0 : kSecondTryDelayMs, after_a_failure ? 1 : 0,
                 int(kMaxFontFileBytes));
  ++tries;
}

std::string published_digest() {
  char* text = published_cjk_font_digest();
  std::string out = text ? text : "";
  std::free(text);
  return out;
}

CjkFontNews failed_try(std::string_view why) {
  std::fprintf(stderr, "swarmlab: the Chinese font: %.*s\n", int(why.size()), why.data());
  forget_cached_cjk_font();
  if (tries < kTries) {
    start_try();
    return CjkFontNews::none;
  }
  fetch = Fetch::given_up;
  missing = true;
  tell_page_cjk_font_missing();
  return CjkFontNews::given_up;
}

}  // namespace
}  // namespace swarmlab

/// The page's answer to fetch_cjk_font: the bytes in a malloc'd buffer (taken over here), or
/// null when nothing came.
extern "C" EMSCRIPTEN_KEEPALIVE void swarmlab_cjk_font_ready(char* data, int size) {
  using namespace swarmlab;
  fetched = data != nullptr;
  received = fetched ? std::string(data, std::size_t(size)) : std::string();
  std::free(data);
  delivered = true;
}

/// The retry button of the page's notice.
extern "C" EMSCRIPTEN_KEEPALIVE void swarmlab_retry_cjk_font() { swarmlab::retry_cjk_font(); }

namespace swarmlab {

std::string_view cjk_font() { return bytes; }

void request_cjk_font() {
  if (fetch == Fetch::idle) start_try();
}

CjkFontNews cjk_font_news() {
  if (pending_news != CjkFontNews::none) {
    const CjkFontNews news = pending_news;
    pending_news = CjkFontNews::none;
    return news;
  }
  if (!delivered) return CjkFontNews::none;
  delivered = false;
  if (!fetched) return failed_try("the fetch failed");
  // No bytes would read as "not here yet" (cjk_font()), and nothing would be tried again.
  if (received.empty()) return failed_try(font_file_problem(received));
  // Only the build's own font goes on to the checks of fonts.cpp.
  if (const std::string want = published_digest(); !want.empty()) {
    const std::string got = sha256_hex(received).substr(0, want.size());
    if (got != want)
      return failed_try("its SHA-256 begins " + got + ", not " + want + " as its published name says");
  }
  bytes = std::move(received);
  fetch = Fetch::here;
  if (missing) tell_page_cjk_font_here();
  missing = false;
  return CjkFontNews::arrived;
}

bool cjk_font_missing() { return missing; }

void refuse_cjk_font(std::string_view why) {
  bytes.clear();
  pending_news = failed_try(why);
}

void retry_cjk_font() {
  if (fetch != Fetch::given_up) return;
  tries = 0;
  start_try();
}

}  // namespace swarmlab
