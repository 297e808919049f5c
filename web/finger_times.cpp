// Fingers stamped with the page's time of their touch event. SDL stamps a finger event with
// the time its handler ran, which on a busy page (a long frame on a school Chromebook) can be
// hundreds of milliseconds after the finger moved; the gestures (ui/input/touch_gestures.h)
// tell a drag from a hold by these stamps, so they must be the event's own.

#include "finger_times.h"

#include <SDL.h>
#include <emscripten/html5.h>

namespace {

double touch_event_ms = 0;  // the page's time of the touch event being dispatched

// Registered for the capture phase on the canvas, so it runs before SDL's own handler.
EM_BOOL note_time(int, const EmscriptenTouchEvent* e, void*) {
  touch_event_ms = e->timestamp;
  return EM_FALSE;  // SDL's handler still runs and decides about the page's default action
}

// Called by SDL as its handler pushes each finger event, before it is queued.
int stamp(void*, SDL_Event* event) {
  if (event->type == SDL_FINGERDOWN || event->type == SDL_FINGERMOTION ||
      event->type == SDL_FINGERUP)
    event->tfinger.timestamp = Uint32(touch_event_ms);
  return 1;
}

}  // namespace

namespace swarmlab {

void stamp_fingers_with_page_time(const char* canvas) {
  emscripten_set_touchstart_callback(canvas, nullptr, EM_TRUE, note_time);
  emscripten_set_touchmove_callback(canvas, nullptr, EM_TRUE, note_time);
  emscripten_set_touchend_callback(canvas, nullptr, EM_TRUE, note_time);
  emscripten_set_touchcancel_callback(canvas, nullptr, EM_TRUE, note_time);
  SDL_AddEventWatch(stamp, nullptr);
}

}  // namespace swarmlab
