// window.swarmlab: the JS API for pages that embed Swarm Lab (a course page, a test), linked
// into swarmlab.js with --post-js after share_link.js. It wraps the C functions of
// web/js_api.cpp:
//   swarmlab.time()        the simulated time of the running preset (a number)
//   swarmlab.state()       what the app shows and runs: { name, edited, playing, t, speed,
//                          selected, ... } (web/README.md lists every field)
//   swarmlab.seek(t, {onprogress}) moves the run to time t, back or forward, a frame's budget
//                          at a time (the page never freezes); returns a Promise of the time
//                          reached. A new seek, Play or Pause, Cancel or Esc cancels it: the
//                          Promise rejects with an Error named 'AbortError' ({ cancelled: true,
//                          t: the time then }). onprogress({ progress: 0 to 1, t }) is called
//                          after each frame while it runs. t before 0 or after the end of the
//                          preset's run: rejected with an Error saying so; nothing changes
//   swarmlab.positions()   lab positions [[x, y, z], ...] of the first 10,000 particles
//   swarmlab.set(changes)  changes what it names, e.g. { theme: 'light', sound: true } (keys in
//                          web/js_set.cpp); an unknown key or a bad value throws Error naming it
//   swarmlab.preset()      the running preset, every edit included, as a JSON string
//   swarmlab.load(json)    opens a preset (a JSON string, or an object); returns true, or, if
//                          it fails validation or is larger than SwarmlabLink.maxPresetBytes
//                          (4 MB of UTF-8), keeps the running preset, shows the message in
//                          the scenario panel and on the page, and throws Error(message); the
//                          message is the CLI's, e.g. "swarmlab.load(): dt: must be > 0"
//   swarmlab.link()        Promise of a share link to the running preset (#lang=...&z=... or
//                          #lang=...&preset=...: it opens in the language in use)
//   swarmlab.copyLink()    the Copy link button: puts that link in the address bar and on the
//                          clipboard, and shows it on the page; Promise of the link
//   swarmlab.openLink(hash) opens the preset of a fragment; Promise of "" or the error message
//   swarmlab.openFile()    the Open preset... button: a file picker, then as load()
//   swarmlab.pickProgressFile() the Load progress... button: a file picker, then the file's
//                          lesson progress in place of the progress now; the message line
//                          says whether it was loaded
//   swarmlab.download()    the Download preset button; returns the file name
//   swarmlab.exportCsv()   the samples as CSV (swarmlab run --csv's columns) as a download;
//                          returns the file name
//   swarmlab.shipped()     the preset list: [{ id: file name, name }]
//   swarmlab.select(i)     selects particle i (0-based; null: none) as a click does, opening its
//                          card and period meter; throws Error naming i when out of range
//   swarmlab.stopwatch(action) the stopwatch's buttons: 'start', 'stop', 'lap' or 'reset';
//                          returns state().stopwatch
//   swarmlab.buttonRect(label) where the scenario panel's button 'Open preset…', 'Download
//                          preset' or 'Copy link' is drawn: { x, y, width, height } in CSS
//                          pixels of the canvas, or null (for tests that click like a person)
//   swarmlab.lessons()     the shipped lessons: [{ id, title, summary, steps }]
//   swarmlab.openLesson(idOrJson) opens a shipped lesson by id, or a lesson (JSON text or an
//                          object); true, or throws Error(message) and keeps what was running
//   swarmlab.lessonState() { id, title, step, steps, text, task } or null; task is null or
//                          { kind, prompt, ... } (web/README.md)
//   swarmlab.lessonAnswer(value) answers the task (a number, or an option's index):
//                          { correct, feedback } (correct null for a prediction; feedback
//                          in plain text as the panel shows it, words for the device in use)
//   swarmlab.lessonNext(), swarmlab.lessonBack() move a step; return lessonState()
//   swarmlab.lessonFinish(), swarmlab.lessonRestart() the summary, or step 1 afresh; return
//                          lessonState()
//   swarmlab.lessonLink(idOrJson) a link that opens the lesson: page address + #lesson= and a
//                          shipped lesson's id, or base64url of a lesson's JSON (text or object)
//   swarmlab.shareLesson(fragment) the lesson panel's Share button: the page's address + the
//                          fragment, copied, put in the address bar and shown
//   swarmlab.welcomeShown() whether the welcome window is showing
//   swarmlab.ready         Promise resolved once main() has started (and a start link is open)
//   swarmlab.frames()      iterations the main loop has run (drawn or not: state().frames_drawn
//                          counts the drawn ones); none while it sleeps
//   swarmlab.sleeping()    whether the main loop sleeps: nothing changes until an input, a call
//                          or a caret's blink (web/frame_sleep.h), so what is shown is settled
//   swarmlab.firstFrameMs  performance.now() at the end of the first frame, or null
//   swarmlab.lastMessage   the last message shown on the page: { kind, text } or null
// A page that opens with a share link starts its preset (decoded before main() runs). A link
// that cannot be decoded or fails validation leaves the default preset running and says why.
(function () {
  'use strict';
  var frames = 0;
  var startLink = null; // what the address's share link decoded to, until main() opens it
  // The page's language (web/page_text.js); a page without it shows the English.
  var pageText = typeof window !== 'undefined' && window.pageText || function (text) {
    var values = Array.prototype.slice.call(arguments, 1);
    return text.replace(/%[-+ #0-9.]*[sdf%]/g, function (c) { return c === '%%' ? '%' : String(values.shift()); });
  };

  function check() {
    if (!runtimeInitialized || !Module.swarmlabMainStarted)
      throw new Error('swarmlab: the app has not started yet (await swarmlab.ready)');
  }

  // What a caller gave, for a message that refuses it: its kind and its value ("the string
  // \"5\"" where String() would print a bare 5 that reads as a number).
  function described(value) {
    var kind = typeof value;
    if (kind === 'string') return 'the string ' + JSON.stringify(value.length > 40 ? value.slice(0, 40) + '...' : value);
    if (kind === 'bigint') return 'the BigInt ' + value + 'n';
    if (kind === 'boolean') return 'the boolean ' + value;
    if (kind === 'number' || value === undefined || value === null) return String(value);
    if (kind === 'function' || kind === 'symbol') return 'a ' + kind;
    return Array.isArray(value) ? 'an array' : 'an object';
  }

  // An index from the caller, checked before it becomes a C int or size_t, where 2^32 + 1
  // would wrap to 1 and 2^53 to 0: a safe integer (exact in a double) from 0 to count - 1.
  // Throws Error naming the call's argument, the value and the range.
  function checkedIndex(call, name, value, count, what) {
    if (!Number.isSafeInteger(value) || value < 0 || value >= count)
      throw new Error(call + ': ' + name + ' must be ' + what + ', an integer from 0 to ' + (count - 1) +
                      ' (' + count + ' of them), not ' + described(value));
    return value;
  }
  function particleCount() { return Module.ccall('swarmlab_particle_count', 'number', [], []); }

  // The frame loop idles while nothing changes (app/ui/frame_demand.h): every call into the app
  // wakes it, except these questions, which only read (a page may ask them every frame).
  var questions = ['swarmlab_preset', 'swarmlab_time', 'swarmlab_state', 'swarmlab_positions',
                   'swarmlab_seek_poll', 'swarmlab_button_rect', 'swarmlab_screen_position',
                   'swarmlab_lessons', 'swarmlab_lesson_state', 'swarmlab_lesson_fragment',
                   'swarmlab_welcome_shown', 'swarmlab_shipped', 'swarmlab_dom_items',
                   'swarmlab_particle_count', 'swarmlab_wake'];
  var ccall = Module.ccall;
  Module.ccall = function (name) {
    var result = ccall.apply(null, arguments);
    if (questions.indexOf(name) < 0) _swarmlab_wake();
    return result;
  };

  function presetText(indent) { return Module.ccall('swarmlab_preset', 'string', ['number'], [indent]); }

  // Calls use(pointer, bytes) with text as UTF-8 in a malloc'd buffer, freed afterwards. ccall's
  // 'string' argument copies onto the wasm stack (5 MB), which a long text overruns ("memory
  // access out of bounds"); the heap grows instead. `bytes` is the text's length, a NUL in it
  // included, which C would take for its end.
  function withHeapText(text, use) {
    var size = lengthBytesUTF8(text) + 1;
    var pointer = _malloc(size);
    if (!pointer) throw new Error('swarmlab: not enough memory for ' + size + ' bytes of text');
    stringToUTF8(text, pointer, size);
    try {
      return use(pointer, size - 1);
    } finally {
      _free(pointer);
    }
  }

  function setStatus(text, isError) {
    withHeapText(String(text), function (pointer) {
      Module.ccall('swarmlab_set_status', null, ['number', 'number'], [pointer, isError ? 1 : 0]);
    });
  }

  // The running preset's name; `shown`: as the page shows it (the fallback in its language).
  function runningName(shown) {
    var none = shown ? pageText('the previous preset') : 'the previous preset';
    try { return JSON.parse(presetText(-1)).name || none; } catch (e) { return none; }
  }

  // The page's message line (web/shell.html has #notice; a page without it gets the console).
  // `text` in English (lastMessage, the console), `shown` in the page's language (the line).
  function notice(kind, text, link, shown) {
    api.lastMessage = { kind: kind, text: text };
    (kind === 'error' ? console.warn : console.log)('swarmlab: ' + text + (link ? ' ' + link : ''));
    if (typeof Module.showNotice === 'function') Module.showNotice(kind, shown || text, link || '');
  }

  // A refusal that the app did not make: the message, said to the page in its language.
  function stillRunning(error, shown) {
    notice('error', error + ' \u2014 still running: \u201c' + runningName() + '\u201d.', '',
           pageText('%s \u2014 still running: \u201c%s\u201d.', shown || error, runningName(true)));
  }

  // Shows a refusal (a message, or { error, shown } from SwarmlabLink) in the scenario panel and
  // on the page; returns the message in English.
  function refuse(refusal) {
    var error = typeof refusal === 'string' ? refusal : refusal.error;
    var shown = typeof refusal === 'string' ? refusal : refusal.shown || refusal.error;
    setStatus(shown, true);
    stillRunning(error, shown);
    return error;
  }

  // Opens JSON text in the app. Returns '' or the error message (shown in the UI and the page).
  // Text over the size limit is refused before any of it is copied into wasm.
  function openJson(text, source, location) {
    text = String(text);
    var bytes = lengthBytesUTF8(text);
    if (bytes > SwarmlabLink.maxPresetBytes) return refuse(SwarmlabLink.tooLarge(source + ': the preset', bytes));
    var error = withHeapText(text, function (pointer, length) {
      return Module.ccall('swarmlab_open_json', 'string', ['number', 'number', 'string', 'string'],
                          [pointer, length, source, location]);
    });
    if (error) stillRunning(error);
    else if (typeof Module.hideNotice === 'function') Module.hideNotice('error');
    return error;
  }

  // A File (picked or dropped): its size is known before it is read, so a huge file is refused
  // without reading it. A lesson file opens as a lesson, anything else as a preset.
  function openFileObject(file) {
    if (file.size > SwarmlabLink.maxPresetBytes) return refuse(SwarmlabLink.tooLarge(file.name, file.size));
    file.text().then(function (text) {
      var lesson = withHeapText(text, function (pointer, length) {
        return Module.ccall('swarmlab_is_lesson', 'number', ['number', 'number'], [pointer, length]);
      });
      if (lesson) openLessonText(text, true, file.name);
      else openJson(text, file.name, file.name);
    });
  }

  // A file picker for JSON (a preset, lesson progress): use(file) with the file picked.
  function pickJsonFile(use) {
    var input = document.createElement('input');
    input.type = 'file';
    input.accept = '.json,application/json';
    input.style.display = 'none';
    input.addEventListener('change', function () {
      var file = input.files && input.files[0];
      input.remove();
      if (file) use(file);
    });
    document.body.appendChild(input);
    input.click();
  }

  // { json } or { error } from SwarmlabLink.read, into the app. Returns '' or the message.
  function openLinkResult(result) {
    if (result.error) return refuse(result);
    if (result.lessonLink !== undefined) return openLessonLink(result.lessonLink);
    if (result.lesson) return openLessonText(result.json, true, 'lesson link');
    return openJson(result.json, 'share link', 'shared-preset.json');
  }

  // Opens a lesson (JSON text, or a shipped lesson's id). Returns '' or the message, which the
  // lesson panel and the page show; the running lesson stays.
  function openLessonText(text, isJson, source) {
    text = String(text);
    var bytes = lengthBytesUTF8(text);
    if (bytes > SwarmlabLink.maxPresetBytes)
      return refuse(SwarmlabLink.tooLarge(source + ': the lesson', bytes));
    var error = withHeapText(text, function (pointer, length) {
      return Module.ccall('swarmlab_open_lesson', 'string', ['number', 'number', 'number', 'string'],
                          [pointer, length, isJson ? 1 : 0, source]);
    });
    if (error) notice('error', error);
    else if (typeof Module.hideNotice === 'function') Module.hideNotice('error');
    return error;
  }

  // The text after #lesson=: the app opens a shipped lesson's id or a lesson's JSON in
  // base64url, and refuses anything else in one sentence. Returns '' or the message.
  function openLessonLink(value) {
    var error = withHeapText(String(value), function (pointer) {
      return Module.ccall('swarmlab_open_lesson_link', 'string', ['number'], [pointer]);
    });
    if (error) notice('error', error);
    else if (typeof Module.hideNotice === 'function') Module.hideNotice('error');
    return error;
  }

  // A link copied (or not: the browser refused) and shown: the status line and the message.
  // `lesson`: the title of the lesson it opens, else it starts the running preset.
  function sayLink(url, copied, lesson) {
    setStatus(copied ? pageText('Link copied to the clipboard (%d characters)', url.length)
                     : pageText('Copy this link from the page or the address bar'), false);
    var how = copied ? 'Link copied to the clipboard' : 'Copy this link';
    var what = lesson !== undefined ? 'opens the lesson \u201c' + lesson + '\u201d' : 'starts \u201c' + runningName() + '\u201d';
    var shown = lesson !== undefined
      ? (copied ? pageText('Link copied to the clipboard: whoever opens it opens the lesson \u201c%s\u201d.', lesson)
                : pageText('Copy this link: whoever opens it opens the lesson \u201c%s\u201d.', lesson))
      : (copied ? pageText('Link copied to the clipboard: whoever opens it starts \u201c%s\u201d.', runningName(true))
                : pageText('Copy this link: whoever opens it starts \u201c%s\u201d.', runningName(true)));
    notice('link', how + ': whoever opens it ' + what + '.', url, shown);
  }

  // The page's link for a lesson fragment: copied, put in the address bar and shown.
  function shareFragment(fragment, title) {
    var url = pageAddress() + withLanguage(fragment);
    history.replaceState(null, '', url);
    return copyText(url).then(function (copied) {
      sayLink(url, copied, String(title));
      return url;
    });
  }

  function lessonFragmentNow() { return Module.ccall('swarmlab_lesson_fragment', 'string', [], []); }

  function lessonStateNow() { return JSON.parse(Module.ccall('swarmlab_lesson_state', 'string', [], [])); }

  function copyText(text) { // Promise: true when on the clipboard
    function fallback() {
      var area = document.createElement('textarea');
      area.value = text;
      area.setAttribute('readonly', '');
      area.style.position = 'fixed';
      area.style.opacity = '0';
      document.body.appendChild(area);
      area.select();
      var ok = false;
      try { ok = document.execCommand('copy'); } catch (e) { ok = false; }
      area.remove();
      if (Module.canvas) Module.canvas.focus();
      return ok;
    }
    // navigator.clipboard exists only in secure contexts (https, localhost); a classroom LAN
    // address is plain http, where the old execCommand('copy') still works after a click.
    if (navigator.clipboard && window.isSecureContext) {
      return navigator.clipboard.writeText(text).then(function () { return true; }, fallback);
    }
    return Promise.resolve(fallback());
  }

  function pageAddress() { return location.href.split('#')[0]; }

  /// A shared link opens in the language it was shared in: #lang= first, then the fragment
  /// (only the fragment from a page without web/page_text.js, which knows no language).
  function withLanguage(fragment) {
    var code = window.swarmlabLanguage;
    return (code ? '#lang=' + encodeURIComponent(code) + '&' : '#') + fragment.replace(/^#/, '');
  }

  // The seeks under way (swarmlab.seek), by id: { t, resolve, reject, onprogress }. The app
  // carries a seek on a frame's budget at a time (app/ui/time/time_controls.h); after every
  // frame each is told its progress, and settled when it ends.
  var seeks = {};
  function followSeeks() {
    if (!Object.keys(seeks).length) return;
    var now = JSON.parse(Module.ccall('swarmlab_seek_poll', 'string', [], []));
    now.ended.forEach(function (end) {
      var seek = seeks[end.id];
      if (!seek) return;
      delete seeks[end.id];
      if (end.reached) return seek.resolve(end.t);
      var e = new Error('swarmlab.seek(' + seek.t + '): cancelled at t = ' + end.t +
                        ' (by a new seek, Play or Pause, Cancel, Esc, or another preset)');
      e.name = 'AbortError';
      e.cancelled = true;
      e.t = end.t;
      seek.reject(e);
    });
    var running = now.running && seeks[now.running.id];
    if (running && running.onprogress) {
      try { running.onprogress({ progress: now.running.progress, t: now.t }); }
      catch (e) { console.warn('swarmlab.seek(): onprogress threw: ' + e); }
    }
  }
  (Module.swarmlabEachFrame = Module.swarmlabEachFrame || []).push(followSeeks);

  var api = {
    firstFrameMs: null,
    lastMessage: null,
    frames: function () { return frames; },
    sleeping: function () { return Module.swarmlabSleeping(); },
    time: function () { check(); return Module.ccall('swarmlab_time', 'number', [], []); },
    state: function () { check(); return JSON.parse(Module.ccall('swarmlab_state', 'string', [], [])); },
    seek: function (t, options) {
      check();
      if (typeof t !== 'number' || !isFinite(t))
        return Promise.reject(new Error('swarmlab.seek(t): t must be a finite number (time units), got ' + described(t)));
      var started = JSON.parse(Module.ccall('swarmlab_seek_start', 'string', ['number'], [t]));
      if (started.error) return Promise.reject(new Error('swarmlab.seek(t): ' + started.error));
      var onprogress = options && typeof options.onprogress === 'function' ? options.onprogress : null;
      var done = new Promise(function (resolve, reject) {
        seeks[started.id] = { t: t, resolve: resolve, reject: reject, onprogress: onprogress };
      });
      followSeeks();
      return done;
    },
    positions: function () { check(); return JSON.parse(Module.ccall('swarmlab_positions', 'string', [], [])); },
    preset: function () { check(); return presetText(2); },
    load: function (json) {
      check();
      var text = typeof json === 'string' ? json : JSON.stringify(json);
      var error = openJson(text, 'swarmlab.load()', 'preset.json');
      if (error) throw new Error(error);
      return true;
    },
    link: function () {
      check();
      return SwarmlabLink.fragment(presetText(-1)).then(function (f) { return pageAddress() + withLanguage(f); });
    },
    copyLink: function () {
      // During a lesson the link is the lesson's: a student who opens it starts the lesson,
      // which sets its own scenes (docs/lessons.md, "Sharing it").
      var lesson = lessonFragmentNow();
      if (lesson) return shareFragment(lesson, lessonStateNow().title);
      return api.link().then(function (url) {
        history.replaceState(null, '', url); // the address bar shows it too; no reload
        return copyText(url).then(function (copied) {
          sayLink(url, copied);
          return url;
        });
      });
    },
    openLink: function (hash) {
      check();
      var pending = SwarmlabLink.read(hash);
      if (!pending) return Promise.resolve('share link: no #preset= or #z= in "' + hash + '"');
      return pending.then(openLinkResult);
    },
    openFile: function () {
      check();
      pickJsonFile(openFileObject);
    },
    // Load progress... (the Lessons menu, the progress notice): a file picker; the file's
    // lesson progress replaces the progress now (js_lessons.cpp says how it went).
    pickProgressFile: function () {
      check();
      pickJsonFile(function (file) {
        if (file.size > SwarmlabLink.maxPresetBytes) return refuse(SwarmlabLink.tooLarge(file.name, file.size));
        file.text().then(function (text) {
          var result = JSON.parse(withHeapText(text, function (pointer) {
            return Module.ccall('swarmlab_load_progress', 'string', ['number'], [pointer]);
          }));
          // The page's message line, a live region: the student hears how it went.
          notice(result.loaded ? 'info' : 'error', result.message);
        });
      });
    },
    download: function () { check(); return Module.ccall('swarmlab_download', 'string', [], []); },
    exportCsv: function () { check(); return Module.ccall('swarmlab_export_csv', 'string', [], []); },
    buttonRect: function (label) {
      check();
      var r = Module.ccall('swarmlab_button_rect', 'string', ['string'], [label]).split(' ').map(Number);
      return r.length === 4 ? { x: r[0], y: r[1], width: r[2], height: r[3] } : null;
    },
    // Touch and layouts: where particle i is drawn ({x, y} CSS pixels, or null off the view),
    // and set({playing, speed, layout, ui_scale, selected, ...}) (web/js_set.cpp's table).
    screenPosition: function (i) {
      check();
      checkedIndex('swarmlab.screenPosition(i)', 'i', i, particleCount(), 'a particle index');
      var p = Module.ccall('swarmlab_screen_position', 'string', ['number'], [i]);
      if (p.indexOf('bad') === 0) checkedIndex('swarmlab.screenPosition(i)', 'i', i, Number(p.slice(4)), 'a particle index');
      if (!p) return null;
      var xy = p.split(' ').map(Number);
      return { x: xy[0], y: xy[1] };
    },
    set: function (settings) {
      check();
      if (settings === null || typeof settings !== 'object' || Array.isArray(settings))
        throw new Error('swarmlab.set(): expects an object such as {playing: false}');
      var error = withHeapText(JSON.stringify(settings), function (pointer) {
        return Module.ccall('swarmlab_set', 'string', ['number'], [pointer]);
      });
      if (error) throw new Error(error);
      return api.state();
    },
    select: function (i) {
      check();
      if (i !== null) checkedIndex('swarmlab.select(i)', 'i', i, particleCount(), 'null or a particle index');
      var refused = Module.ccall('swarmlab_select', 'number', ['number'], [i === null ? -1 : i]);
      if (refused >= 0) checkedIndex('swarmlab.select(i)', 'i', i, refused, 'null or a particle index');
      return i;
    },
    stopwatch: function (action) {
      check();
      var code = ['start', 'stop', 'lap', 'reset'].indexOf(action);
      if (code < 0) throw new Error('swarmlab.stopwatch(): ' + JSON.stringify(action) + ' is not start, stop, lap or reset');
      Module.ccall('swarmlab_stopwatch', null, ['number'], [code]);
      return api.state().stopwatch;
    },
    // Lessons (docs/lessons.md, web/README.md).
    lessons: function () {
      check();
      return JSON.parse(Module.ccall('swarmlab_lessons', 'string', [], [])).map(function (l) {
        return { id: l.id, title: l.title, summary: l.summary, steps: l.steps };
      });
    },
    openLesson: function (idOrJson) {
      check();
      var isJson = typeof idOrJson !== 'string' || /^\s*\{/.test(idOrJson);
      var text = typeof idOrJson === 'string' ? idOrJson : JSON.stringify(idOrJson);
      var error = openLessonText(text, isJson, 'swarmlab.openLesson()');
      if (error) throw new Error(error);
      return true;
    },
    lessonState: function () { check(); return lessonStateNow(); },
    lessonAnswer: function (value) {
      check();
      if (typeof value !== 'number' || !isFinite(value))
        throw new Error('swarmlab.lessonAnswer(value): value must be a finite number (a measurement, or an option\'s index), not ' + described(value));
      var result = JSON.parse(Module.ccall('swarmlab_lesson_answer', 'string', ['number'], [value]));
      if (result.error) throw new Error('swarmlab.lessonAnswer(value): ' + result.error);
      return result;
    },
    lessonNext: function () { check(); return JSON.parse(Module.ccall('swarmlab_lesson_move', 'string', ['number'], [1])); },
    lessonBack: function () { check(); return JSON.parse(Module.ccall('swarmlab_lesson_move', 'string', ['number'], [-1])); },
    lessonFinish: function () { check(); return JSON.parse(Module.ccall('swarmlab_lesson_finish', 'string', ['number'], [1])); },
    lessonRestart: function () { check(); return JSON.parse(Module.ccall('swarmlab_lesson_finish', 'string', ['number'], [-1])); },
    lessonLink: function (idOrJson) {
      // A shipped lesson's id links by its id; a lesson (JSON text or an object) by its JSON.
      if (typeof idOrJson === 'string' && !/^\s*\{/.test(idOrJson)) {
        check();
        var known = api.lessons().some(function (l) { return l.id === idOrJson; });
        if (!known) throw new Error('swarmlab.lessonLink(): ' + JSON.stringify(idOrJson) + ' is not a shipped lesson\'s id');
        return pageAddress() + '#lesson=' + idOrJson;
      }
      var text = typeof idOrJson === 'string' ? idOrJson : JSON.stringify(idOrJson);
      return pageAddress() + '#lesson=' + SwarmlabLink.toBase64url(new TextEncoder().encode(text));
    },
    // The lesson panel's Share button (js_lessons.cpp): Promise of the link.
    shareLesson: function (fragment) {
      check();
      return shareFragment(fragment, (lessonStateNow() || {}).title);
    },
    welcomeShown: function () { check(); return Module.ccall('swarmlab_welcome_shown', 'number', [], []) === 1; },
    shipped: function () {
      check();
      return Module.ccall('swarmlab_shipped', 'string', [], []).split('\n').filter(Boolean).map(function (line) {
        var tab = line.indexOf('\t');
        return { id: line.slice(0, tab), name: line.slice(tab + 1) };
      });
    },
  };

  // A share link in the address: decode it (deflate is asynchronous) before main() runs.
  if (typeof location !== 'undefined') {
    var pending = SwarmlabLink.read(location.hash);
    if (pending) {
      addRunDependency('swarmlab-share-link');
      pending.then(function (result) {
        startLink = result;
        removeRunDependency('swarmlab-share-link');
      });
    }
  }
  // Called by main() once the app exists, before the first frame.
  Module.swarmlabStarted = function () {
    Module.swarmlabMainStarted = true;
    if (startLink) openLinkResult(startLink);
    startLink = null;
  };
  api.ready = new Promise(function (resolve) { addOnPostRun(function () { resolve(api); }); });

  if (typeof window !== 'undefined') {
    // A link pasted into the address bar of an open page changes only the fragment.
    // The fragment is read and decoded once: a long one costs the browser time on every read.
    window.addEventListener('hashchange', function () {
      if (!Module.swarmlabMainStarted) return;
      var pending = SwarmlabLink.read(location.hash);
      if (pending) pending.then(openLinkResult);
    });
    // Leaving the page with edits asks first; without edits it does not (nothing is lost).
    window.addEventListener('beforeunload', function (e) {
      // Inside a course page (?embed) never: the course page's own links leave without asking.
      if (!Module.swarmlabMainStarted) return;
      var now = api.state();
      if (now.embed || !now.edited) return;
      e.preventDefault();
      e.returnValue = '';
    });
    // A hidden tab pauses its run (unless View > Keep running in a hidden tab), and says so
    // when the student comes back.
    document.addEventListener('visibilitychange', function () {
      if (!Module.swarmlabMainStarted) return;
      var paused = Module.ccall('swarmlab_page_hidden', 'number', ['number'],
                                [document.visibilityState === 'hidden' ? 1 : 0]);
      if (paused)
        notice('info', 'Paused while this tab was hidden: press Play to go on.', '',
               pageText('Paused while this tab was hidden: press Play to go on.'));
    });
    // A file dropped on the page opens like Open preset (a lesson file as a lesson).
    window.addEventListener('dragover', function (e) { e.preventDefault(); });
    window.addEventListener('drop', function (e) {
      e.preventDefault();
      var file = e.dataTransfer && e.dataTransfer.files && e.dataTransfer.files[0];
      if (file && Module.swarmlabMainStarted) openFileObject(file);
    });
  }

  // After each iteration of the main loop (Emscripten's hook around it).
  Module.postMainLoop = function () {
    if (!runtimeInitialized) return;
    frames++;
    // After a frame the app drew (web_main.cpp): one that was not drawn changed nothing to follow.
    if (Module.swarmlabDrew) (Module.swarmlabEachFrame || []).forEach(function (f) { f(); });
    Module.swarmlabDrew = false;
    if (api.firstFrameMs === null) {
      api.firstFrameMs = performance.now();
      if (Module.onFirstFrame) Module.onFirstFrame(api.firstFrameMs);
    }
  };
  if (typeof window !== 'undefined') window.swarmlab = api;
  Module.swarmlab = api;
})();
