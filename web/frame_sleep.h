#pragma once
// The browser's frame loop asleep while nothing changes. A loop that only returns when no frame
// is wanted (frame_demand.h) still asks the browser for sixty animation frames a second, and
// Chrome's own work for each of them costs about 4 % of a core with nothing drawn; asleep, the
// loop asks for none. An input on the page, a call into the app or the caret's next blink
// (frame_sleep.js) wakes it.

#include "ui/main_loop.h"

namespace swarmlab {

/// Called by the frame loop instead of a frame that is not wanted: the loop stops asking for
/// animation frames until woken; a text field's caret sets a timer for its next blink.
void sleep_frames(Frontend& frontend);

/// Called by the frame loop while nothing can be drawn (the WebGL context lost): no animation
/// frame is asked for until something wakes the loop (the context back, an input, a call).
void sleep_until_woken();

/// At the start of each iteration of the frame loop: after a sleep the frame clock starts
/// afresh, so that the sleep is not the next frame's time (a run pressed into play does not
/// make up the idle minutes).
void after_sleep(Frontend& frontend);

/// Something changed from outside (a call from the page, a font that arrived, the context
/// back): a frame is wanted and a sleeping loop wakes.
void wake_frames(Frontend& frontend);

}  // namespace swarmlab
