// The page's side of the frame loop's sleep (web/frame_sleep.h): while nothing changes the loop
// asks the browser for no animation frame; any input on the page, or the caret's next blink,
// starts it again. The input itself reaches the app through SDL's own listeners, which run
// after these (capture on the window comes first) and queue it for the woken loop.
(function () {
  'use strict';
  var asleep = false;
  var timer = null;

  function resume() {
    if (!asleep) return;
    asleep = false;
    if (timer !== null) clearTimeout(timer);
    timer = null;
    Module.resumeMainLoop();
  }

  // wakeInMs: when a frame is wanted with nothing else happening (a caret's blink), or a huge
  // number: only an input or a call wakes the loop.
  Module.swarmlabSleep = function (wakeInMs) {
    asleep = true;
    if (wakeInMs < 1e7) timer = setTimeout(resume, Math.max(0, wakeInMs));
  };
  Module.swarmlabResume = resume;
  Module.swarmlabSleeping = function () { return asleep; };

  if (typeof window === 'undefined') return;
  ['keydown', 'keyup', 'keypress', 'compositionend', 'pointerdown', 'pointermove', 'pointerup',
   'pointercancel', 'mousedown', 'mousemove', 'mouseup', 'wheel', 'touchstart', 'touchmove',
   'touchend', 'touchcancel', 'focus', 'blur', 'resize', 'orientationchange',
   'fullscreenchange'].forEach(function (type) {
    window.addEventListener(type, resume, { capture: true, passive: true });
  });
})();
