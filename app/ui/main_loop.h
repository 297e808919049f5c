#pragma once
// The one loop body of the window, shared by the desktop (a plain loop in desktop.cpp) and the
// browser (emscripten_set_main_loop_arg calling run_frame).

#include <chrono>
#include <deque>
#include <memory>

#include "ui/app.h"
#include "ui/classroom/classroom_outputs.h"
#include "ui/frame_demand.h"
#include "ui/platform/sdl_window.h"

namespace swarmlab {

struct Frontend {
  SdlWindow window;
  std::unique_ptr<App> app;
  std::chrono::steady_clock::time_point last_frame = std::chrono::steady_clock::now();
  bool running = true;
  ClassroomOutputs outputs;  ///< theme, fullscreen, title and live region, sound
  FrameDemand demand;        ///< whether a frame is due, or the window idles
  /// Keyboard events held for the frames after this one (main_loop.cpp: ImGui 1.86 sees a key
  /// once a frame).
  std::deque<SDL_Event> waiting_keys;
};

/// Whether run_frame has anything to do now: an event waits, or the demand wants a frame (a
/// run plays, the last change is settling, a caret blinks). When not, the frame clock moves on,
/// so that the next frame's time is its own and not the idle stretch before it.
bool frame_wanted(Frontend& frontend);

/// Handles the pending events, runs and draws one frame and presents it; before presenting,
/// calls before_present (e.g. to read the pixels for a screenshot) when given. Returns false
/// once the window should close.
bool run_frame(Frontend& frontend, void (*before_present)(Frontend&) = nullptr);

}  // namespace swarmlab
