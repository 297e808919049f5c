// The canvas's WebGL context lost and restored. A phone, a tablet or a Chromebook drops it when
// the GPU resets, memory runs short or the tab stays long in the background; the page then has
// a context whose every call does nothing, until the browser restores it, empty, if the page
// asked for that (by preventing the loss's default action). SDL2 2.26's Emscripten port
// listens for neither event (its src/video/emscripten handles no webglcontext* event), so the
// app listens itself, on the canvas SDL drew into.
//
// Lost: no frame runs (web_main.cpp asks context_lost()), so neither the run nor the student's
// edits change while nothing can be seen, and no GL call reaches the lost context; the GL
// objects are released (ui/gl_context_life.h) and the page shows one calm line (shell.html's
// #notice, a live region). Restored: every GL object is made again, the frames go on from where
// they stopped, the line goes and the live region says the picture is back.

#include "context_loss.h"

#include <emscripten.h>
#include <emscripten/html5.h>

#include "frame_sleep.h"
#include "ui/gl_context_life.h"

namespace {

bool lost = false;

EM_BOOL on_lost(int, const void*, void* frontend) {
  if (!lost) {
    lost = true;
    swarmlab::release_gl_objects(*static_cast<swarmlab::Frontend*>(frontend));
    EM_ASM({
      if (Module.onContextLost) Module.onContextLost();
    });
  }
  return EM_TRUE;  // preventDefault: the browser may restore the context
}

EM_BOOL on_restored(int, const void*, void* frontend) {
  if (lost) {
    swarmlab::create_gl_objects(*static_cast<swarmlab::Frontend*>(frontend));
    lost = false;
    swarmlab::wake_frames(*static_cast<swarmlab::Frontend*>(frontend));
    EM_ASM({
      if (Module.onContextRestored) Module.onContextRestored();
    });
  }
  return EM_TRUE;
}

}  // namespace

namespace swarmlab {

void survive_context_loss(const char* canvas, Frontend& frontend) {
  emscripten_set_webglcontextlost_callback(canvas, &frontend, EM_FALSE, on_lost);
  emscripten_set_webglcontextrestored_callback(canvas, &frontend, EM_FALSE, on_restored);
}

bool context_lost() { return lost; }

}  // namespace swarmlab
