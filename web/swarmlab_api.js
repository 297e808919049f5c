// window.swarmlab: the page's JS API, linked into swarmlab.js with --post-js.
// It wraps functions the C++ app must export (extern "C" + EMSCRIPTEN_KEEPALIVE; the link
// fails if one is missing, see SWARMLAB_WEB_EXPORTS in web/CMakeLists.txt):
//   double      swarmlab_time()                 -> swarmlab.time()      simulated clock (number)
//   const char* swarmlab_preset()               -> swarmlab.preset()    current preset (object, from JSON)
//   const char* swarmlab_load(const char* json) -> swarmlab.load(json)  json: string or object;
//                                                 returns true, throws Error(message) if rejected
// and adds, independent of the app:
//   swarmlab.ready          Promise resolved once main() has started
//   swarmlab.frames()       number of frames the main loop has run (requestAnimationFrame callbacks)
//   swarmlab.firstFrameMs   performance.now() at the end of the first frame (ms since navigation), or null
(function () {
  var frames = 0;
  var api = {
    firstFrameMs: null,
    frames: function () { return frames; },
    time: function () { check(); return Module.ccall('swarmlab_time', 'number', [], []); },
    preset: function () { check(); return JSON.parse(Module.ccall('swarmlab_preset', 'string', [], [])); },
    load: function (json) {
      check();
      var text = typeof json === 'string' ? json : JSON.stringify(json);
      var error = Module.ccall('swarmlab_load', 'string', ['string'], [text]);
      if (error) throw new Error('swarmlab.load: ' + error);
      return true;
    },
  };
  function check() {
    if (!runtimeInitialized) throw new Error('swarmlab: the app has not started yet (await swarmlab.ready)');
  }
  api.ready = new Promise(function (resolve) { addOnPostRun(function () { resolve(api); }); });

  // Count main-loop frames: emscripten_set_main_loop(..., fps = 0, ...) runs on requestAnimationFrame.
  if (typeof window !== 'undefined' && window.requestAnimationFrame) {
    var raf = window.requestAnimationFrame.bind(window);
    window.requestAnimationFrame = function (callback) {
      return raf(function (t) {
        callback(t);
        if (runtimeInitialized) {
          frames++;
          if (api.firstFrameMs === null) {
            api.firstFrameMs = performance.now();
            if (Module.onFirstFrame) Module.onFirstFrame(api.firstFrameMs);
          }
        }
      });
    };
  }
  if (typeof window !== 'undefined') window.swarmlab = api;
  Module.swarmlab = api;
})();
