#include "frame_sleep.h"

#include <emscripten.h>

#include <chrono>
#include <cmath>

namespace {

bool asleep = false;

// wake_in_ms: a frame wanted then with nothing else happening (frame_sleep.js's timer).
void sleep_for_ms(double wake_in_ms) {
  asleep = true;
  emscripten_pause_main_loop();
  EM_ASM({ Module.swarmlabSleep($0); }, wake_in_ms);
}

}  // namespace

namespace swarmlab {

void sleep_frames(Frontend& frontend) {
  sleep_for_ms(frontend.demand.seconds_to_next(steady_seconds()) * 1000);
}

void sleep_until_woken() { sleep_for_ms(INFINITY); }

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
