#include "ui/gl_context_life.h"

#include <backends/imgui_impl_opengl3.h>

#include <cstdio>
#include <vector>

#include "ui/kit/gl_api.h"

namespace swarmlab {
namespace {

bool minimised(SDL_Window* window) {
  return (SDL_GetWindowFlags(window) & (SDL_WINDOW_MINIMIZED | SDL_WINDOW_HIDDEN)) != 0;
}

bool asks_to_close(const SDL_Event& e) {
  return e.type == SDL_QUIT ||
         (e.type == SDL_WINDOWEVENT && e.window.event == SDL_WINDOWEVENT_CLOSE);
}

double run_time(Frontend& f) { return f.app && f.app->state().run ? f.app->state().run->time() : 0; }

}  // namespace

void release_gl_objects(Frontend& f) {
  // Shutdown, not DestroyDeviceObjects: ImGui 1.86 keeps the sizes of its vertex and index
  // buffers across DestroyDeviceObjects, and would write into new buffers that have no storage.
  ImGui_ImplOpenGL3_Shutdown();
  if (f.app) f.app->renderer().release_gl_objects();
}

void create_gl_objects(Frontend& f) {
  ImGui_ImplOpenGL3_Init(kGlslVersion);
  if (f.app) f.app->renderer().create_gl_objects();
  f.last_frame = std::chrono::steady_clock::now();
  f.demand.wake();  // the new context's picture is empty: drawn again even when paused and still
}

void hold_while_minimised(Frontend& f) {
  SDL_Window* window = f.window.window;
  if (!minimised(window)) return;
  std::printf("swarmlab: the window is minimised: no frames until it shows again (t = %.9g)\n",
              run_time(f));
  std::fflush(stdout);
  std::vector<SDL_Event> waiting;
  SDL_Event e;
  while (minimised(window)) {
    // The timeout only bounds how long a change of the flags without an event would go unseen.
    if (!SDL_WaitEventTimeout(&e, 500)) continue;
    waiting.push_back(e);
    if (asks_to_close(e)) break;
  }
  // The events still queued behind those taken, then all of them back, in their order.
  SDL_PumpEvents();
  while (SDL_PeepEvents(&e, 1, SDL_GETEVENT, SDL_FIRSTEVENT, SDL_LASTEVENT) == 1)
    waiting.push_back(e);
  for (SDL_Event& held : waiting) SDL_PushEvent(&held);
  f.last_frame = std::chrono::steady_clock::now();
  f.demand.wake();
  std::printf("swarmlab: %s: frames go on (t = %.9g)\n",
              minimised(window) ? "the minimised window is asked to close" : "the window shows again",
              run_time(f));
  std::fflush(stdout);
}

}  // namespace swarmlab
