// A mouse press with no motion before it (a touchscreen or an interactive whiteboard acting as
// a mouse, a pen): SDL's canvas handler gives a press the position of the last mousemove, so
// the press would land where the pointer was before. The press's own position is sent as a
// move first, in the capture phase, before SDL's handler sees the press. Linked with --post-js.
(function () {
  'use strict';
  if (typeof document === 'undefined') return;
  var canvas = Module.canvas || document.getElementById('canvas');
  if (!canvas) return;
  var lastX = NaN, lastY = NaN;
  canvas.addEventListener('mousemove', function (e) { lastX = e.clientX; lastY = e.clientY; }, true);
  canvas.addEventListener('mousedown', function (e) {
    if (e.clientX === lastX && e.clientY === lastY) return;
    canvas.dispatchEvent(new MouseEvent('mousemove', {
      clientX: e.clientX, clientY: e.clientY, screenX: e.screenX, screenY: e.screenY,
      buttons: 0, bubbles: true, cancelable: true, view: window,
    }));
  }, true);
})();
