// The on-screen keyboard for number fields: a phone shows its keyboard only for a focused
// HTML input, never for a canvas. While a number field of the app is being edited with
// fingers (web/touch_keyboard.cpp), an <input inputmode="decimal"> lies over it with its
// text; Enter, or leaving it, hands the text back to the field. Linked with --post-js.
(function () {
  'use strict';
  if (typeof document === 'undefined') return;
  var input = null, shown = false;

  function make() {
    input = document.createElement('input');
    input.id = 'swarmlab-number';
    input.type = 'text';
    input.setAttribute('inputmode', 'decimal');
    input.setAttribute('enterkeyhint', 'done');
    input.setAttribute('aria-label', 'Value');
    input.autocomplete = 'off';
    input.style.cssText = 'position:fixed;z-index:3;box-sizing:border-box;margin:0;padding:0 6px;' +
      'font:16px system-ui,sans-serif;color:#eceff4;background:#1f2533;border:2px solid #88c0d0;border-radius:3px;';
    input.hidden = true;
    function commit() {
      if (!shown) return;
      shown = false;
      input.hidden = true;
      Module.ccall('swarmlab_type_text', null, ['string'], [input.value]);
    }
    input.addEventListener('keydown', function (e) {
      e.stopPropagation(); // the app's keys (Space, R, ...) are not for this field
      if (e.key === 'Enter') { e.preventDefault(); commit(); input.blur(); }
    });
    input.addEventListener('blur', commit);
    document.body.appendChild(input);
  }

  // Once a frame: follow the field being edited.
  function follow() {
    if (!Module.swarmlabMainStarted) return;
    var field = Module.ccall('swarmlab_text_field', 'string', [], []);
    if (!field) {
      if (shown) { shown = false; input.hidden = true; input.blur(); }
      return;
    }
    if (!input) make();
    var tab = field.indexOf('\t');
    var r = field.slice(0, tab).split(' ').map(Number);
    input.style.left = r[0] + 'px';
    input.style.top = r[1] + 'px';
    input.style.width = Math.max(r[2], 80) + 'px';
    input.style.height = Math.max(r[3], 32) + 'px';
    if (!shown) {
      shown = true;
      input.value = field.slice(tab + 1);
      input.hidden = false;
      input.focus();
      input.select();
    }
  }
  Module.swarmlabEachFrame = (Module.swarmlabEachFrame || []).concat([follow]);
})();
