// The frame loop for the browser, as two macros (the pattern of Dear ImGui's
// examples/libs/emscripten/emscripten_mainloop_stub.h, but with emscripten_set_main_loop_arg
// and no global std::function):
//
//     SWARMLAB_MAINLOOP_BEGIN
//     {
//         ... one frame: poll events, simulate, draw ...
//     }
//     SWARMLAB_MAINLOOP_END;
//
// The block is a lambda capturing main()'s locals by reference. emscripten_set_main_loop_arg(...,
// simulate_infinite_loop = true) never returns to main(): it unwinds the JS stack but keeps
// main()'s C stack frame (and so the captured locals and the lambda itself) alive for the page's
// lifetime. fps = 0 drives the loop by requestAnimationFrame (the page's frame counter relies on
// that). Natively (for a shared app main) the same block runs in an ordinary loop until
// swarmlab_mainloop_quit() is called.
#pragma once

#ifdef __EMSCRIPTEN__
#include <emscripten.h>

template <class Frame>
inline void swarmlab_run_main_loop(Frame& frame) {
  emscripten_set_main_loop_arg([](void* f) { (*static_cast<Frame*>(f))(); }, &frame, 0, true);
}
inline void swarmlab_mainloop_quit() { emscripten_cancel_main_loop(); }

#define SWARMLAB_MAINLOOP_BEGIN auto swarmlab_frame_ = [&]()
#define SWARMLAB_MAINLOOP_END swarmlab_run_main_loop(swarmlab_frame_)

#else

inline bool& swarmlab_mainloop_running() {
  static bool running = true;
  return running;
}
inline void swarmlab_mainloop_quit() { swarmlab_mainloop_running() = false; }

#define SWARMLAB_MAINLOOP_BEGIN auto swarmlab_frame_ = [&]()
#define SWARMLAB_MAINLOOP_END \
  while (swarmlab_mainloop_running()) swarmlab_frame_()

#endif
