// The browser entry of Swarm Lab: the desktop's window, App and frame loop (app/desktop) with
// the browser's preset store and storage buttons, driven by requestAnimationFrame and asleep
// while nothing changes (frame_sleep.h); and the page's side of that loop: its wake-up and a
// hidden tab.

#include <emscripten.h>

#include <memory>
#include <string>

#include "context_loss.h"
#include "finger_times.h"
#include "frame_sleep.h"
#include "lessons/lesson_file.h"
#include "ui/classroom/presentation.h"
#include "ui/main_loop.h"
#include "ui/platform/language_memory.h"
#include "storage_controls.h"
#include "web_app.h"
#include "web_preset_store.h"

namespace {

swarmlab::Frontend frontend;  // lives as long as the page

}  // namespace

swarmlab::App* swarmlab::web_app() { return frontend.app.get(); }

extern "C" {

/// The page changed something the app shows (web/swarmlab_api.js calls this after every call
/// that is not a question, a file or font that arrived): the idle frame loop draws again.
EMSCRIPTEN_KEEPALIVE void swarmlab_wake() { swarmlab::wake_frames(frontend); }

/// The page was hidden (1) or shown (0): returns 1 when the run was paused while it was hidden
/// (the page then says so). A run kept going in a hidden tab is driven by a timer, since the
/// browser gives a hidden page no animation frames.
EMSCRIPTEN_KEEPALIVE int swarmlab_page_hidden(int hidden) {
  if (!frontend.app) return 0;
  swarmlab::AppState& state = frontend.app->state();
  const bool paused = swarmlab::set_page_hidden(state, hidden != 0);
  if (hidden && state.playing)
    emscripten_set_main_loop_timing(EM_TIMING_SETTIMEOUT, 250);
  else
    emscripten_set_main_loop_timing(EM_TIMING_RAF, 1);
  swarmlab::wake_frames(frontend);
  return paused ? 1 : 0;
}

}  // extern "C"

int main() {
  std::string error;
  frontend.window = swarmlab::open_window("Swarm Lab", 1280, 720, error);
  if (!frontend.window.window) {
    EM_ASM(
        {
          if (Module.onAbort) Module.onAbort(UTF8ToString($0));
        },
        error.c_str());
    return 1;
  }
  swarmlab::stamp_fingers_with_page_time("#canvas");
  frontend.app = std::make_unique<swarmlab::App>(swarmlab::make_web_preset_store("/presets"),
                                                 /*preset_location=*/"",
                                                 /*fixed_frame_time=*/false);
  frontend.app->state().storage_controls = swarmlab::draw_storage_controls;
  frontend.app->state().presentation.can_be_hidden = true;
  // Lessons embedded at /lessons (assets/lessons); progress and the welcome in localStorage.
  frontend.app->state().lessons.load("/lessons", swarmlab::make_web_progress_store(),
                                     swarmlab::shipped_preset_lookup("/presets"));
  swarmlab::install_lesson_share(frontend.app->state());
  swarmlab::survive_context_loss("#canvas", frontend);
  // The language the page chose (#lang=, the last choice, the browser's: web/page_text.js).
  frontend.app->state().language.pending = swarmlab::startup_language();
  // A share link in the address replaces the default preset before the first frame.
  EM_ASM({
    if (Module.swarmlabStarted) Module.swarmlabStarted();
  });
  // fps = 0: one frame per requestAnimationFrame; never returns (main's stack frame stays).
  // Scenario > Quit stops the frames, and the page offers to start again.
  emscripten_set_main_loop_arg(
      [](void* p) {
        swarmlab::Frontend& f = *static_cast<swarmlab::Frontend*>(p);
        swarmlab::after_sleep(f);
        // Nothing can be drawn: the run waits, and the loop sleeps until the context is back.
        if (swarmlab::context_lost()) {
          swarmlab::sleep_until_woken();
          return;
        }
        // Paused and still, the loop sleeps until something changes (frame_demand.h).
        if (!swarmlab::frame_wanted(f)) {
          swarmlab::sleep_frames(f);
          return;
        }
        // The page follows a drawn frame (the parallel DOM, a seek's progress), not an idle one.
        EM_ASM({ Module.swarmlabDrew = true; });
        if (!swarmlab::run_frame(f)) {
          emscripten_cancel_main_loop();
          EM_ASM({
            if (Module.onQuit) Module.onQuit();
          });
        }
      },
      &frontend, 0, true);
  return 0;
}
