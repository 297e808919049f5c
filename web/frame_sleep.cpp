#include "frame_sleep.h"

#include <emscripten.h>

#include <chrono>

namespace {

bool asleep = false;

}  // namespace

namespace swarmlab {

void sleep_frames(Frontend& frontend) {
  const double wake_in_ms = frontend.demand.seconds_to_next(steady_seconds()) * 1000;
  asleep = true;
  emscripten_pause_main_loop();
  EM_ASM({ Module.swarmlabSleep($0); }, wake_in_ms);
}

void sleep_until_woken() {
  asleep = true;
  emscripten_pause_main_loop();
  EM_ASM({ Module.swarmlabSleep(Infinity); });
}

void after_sleep(Frontend& frontend) {
  if (!asleep) return;
  asleep = false;
  frontend.last_frame = std::chrono::steady_clock::now();
}

void wake_frames(Frontend& frontend) {
  frontend.demand.wake();
  if (asleep) EM_ASM({ Module.swarmlabResume(); });
}

}  // namespace swarmlab
