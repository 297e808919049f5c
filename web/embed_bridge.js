// Embedding in a course page (Moodle, Canvas, a teacher's site): the embed flag and the
// postMessage bridge. Linked into swarmlab.js with --post-js after swarmlab_api.js.
//
// The page's own address says everything; the app never reads its parent (no
// window.parent.document, no document.referrer):
//   ?embed (or #embed)          the app without its menu bar and welcome (swarmlab.set({embed}),
//                               app/ui/classroom/embedding.h)
//   ?origins=A,B (or #origins=) the pages allowed to drive the app through postMessage: exact
//                               origins (https://moodle.example.org), comma-separated; an entry
//                               with a path, a query or another scheme than http(s) is ignored
//                               (and said so on the console). Without it there is no bridge.
//
// A request from an allowed origin:  { swarmlab: 1, id, call: "state", args: [] }
// is answered to its window, at its origin, with  { swarmlab: 1, id, result }  or
// { swarmlab: 1, id, error: "message" }. id is the caller's: a string of at most 200
// characters or a number. The calls are window.swarmlab's (the table below) except openFile,
// copyLink and shareLesson (a file picker or a clipboard needs the student's own click in the
// frame, and the frame's address bar is not seen); `ready` answers true once the app runs;
// `lastMessage` is swarmlab.lastMessage. Calls are run in the order they arrive, each after
// the app has started; a call that returns a Promise is answered when it settles, and the
// next call waits for that, except after seek (a new seek, or state() to follow its progress,
// goes on at once; a seek cancelled by a new one is answered with its error).
// Once the app runs it tells its parent window, at each allowed origin only:
// { swarmlab: 1, event: "ready", embed }.
// A message from an origin not on the list is ignored, never answered. A message that is no
// object with a `swarmlab` key is someone else's and ignored. Anything else that is wrong (an
// unknown call, wrong arguments, another version, a message over 4 MB + 64 KB of JSON, data
// that is not JSON such as a cycle) gets an error reply naming what is wrong.
(function () {
  'use strict';
  if (typeof window === 'undefined' || typeof location === 'undefined') return;
  var api = Module.swarmlab;

  var kVersion = 1;
  var kMaxIdChars = 200;
  // A preset or a lesson may be 4 MB (SwarmlabLink.maxPresetBytes); the rest of a message is small.
  var kMaxMessageChars = SwarmlabLink.maxPresetBytes + 65536;

  // The address's key=value pairs, from the query and then the fragment ('&'-separated, as the
  // share links are). A #preset= link may be megabytes: only its key is looked at.
  function addressValues(key) {
    var values = [];
    [location.search, location.hash].forEach(function (part) {
      part.replace(/^[?#]/, '').split('&').forEach(function (pair) {
        var eq = pair.indexOf('=');
        if ((eq < 0 ? pair : pair.slice(0, eq)) !== key) return;
        var value = eq < 0 ? '' : pair.slice(eq + 1);
        try { value = decodeURIComponent(value.replace(/\+/g, ' ')); } catch (e) { /* as it is */ }
        values.push(value);
      });
    });
    return values;
  }

  // An origin as a browser writes event.origin, or null for anything that is not one.
  function exactOrigin(text) {
    // The URL parser drops a tab or a newline without a word; the list is refused them instead.
    if (/[\u0000-\u001f\u007f-\u009f]/.test(text)) return null;
    var url;
    try { url = new URL(text); } catch (e) { return null; }
    if (url.protocol !== 'https:' && url.protocol !== 'http:') return null;
    // As written, but for the case of letters and a trailing '/': the parser's own mending
    // (http:///host, /. at the end, a default port) is no origin that was meant.
    return text.replace(/\/$/, '').toLowerCase() === url.origin ? url.origin : null;
  }

  var embedded = addressValues('embed').some(function (v) { return v !== '0' && v !== 'false'; });
  var allowed = [];
  addressValues('origins').forEach(function (list) {
    list.split(',').forEach(function (entry) {
      entry = entry.trim();
      if (!entry) return;
      var origin = exactOrigin(entry);
      if (origin) { if (allowed.indexOf(origin) < 0) allowed.push(origin); }
      else console.warn('swarmlab: ?origins=: "' + entry + '" is not an origin such as https://moodle.example.org; ignored');
    });
  });

  // The embed flag goes in before the first frame (main() calls swarmlabStarted).
  var started = Module.swarmlabStarted;
  Module.swarmlabStarted = function () {
    started.apply(this, arguments);
    if (embedded) api.set({ embed: true });
  };

  if (!allowed.length) return;

  // What each call takes: its arguments' kinds, all required.
  var calls = {
    ready: [], state: [], time: [], preset: [], positions: [], shipped: [], frames: [], lastMessage: [],
    load: ['json'], set: ['object'], seek: ['number'], select: ['indexOrNull'], stopwatch: ['string'],
    link: [], openLink: ['string'], download: [], exportCsv: [], screenPosition: ['index'],
    buttonRect: ['string'], welcomeShown: [],
    lessons: [], openLesson: ['json'], lessonState: [], lessonAnswer: ['number'], lessonNext: [],
    lessonBack: [], lessonFinish: [], lessonRestart: [], lessonLink: ['json'],
  };
  var kinds = {
    json: ['JSON text or an object', function (v) { return typeof v === 'string' || (v !== null && typeof v === 'object'); }],
    object: ['an object', function (v) { return v !== null && typeof v === 'object' && !Array.isArray(v); }],
    number: ['a finite number', function (v) { return typeof v === 'number' && isFinite(v); }],
    // Indices are safe integers (exact in a double); the call itself checks them against N.
    index: ['an integer from 0 to 2^53 - 1', function (v) { return Number.isSafeInteger(v) && v >= 0; }],
    indexOrNull: ['an integer from 0 to 2^53 - 1 or null', function (v) { return v === null || (Number.isSafeInteger(v) && v >= 0); }],
    string: ['a string', function (v) { return typeof v === 'string'; }],
  };

  // The app running, or the reason it never will (Module.onAbort: no WebGL2, a crash).
  var failure = null;
  var running = new Promise(function (resolve, reject) {
    api.ready.then(resolve);
    var abort = Module.onAbort;
    Module.onAbort = function (what) {
      failure = 'the app stopped: ' + what;
      reject(new Error(failure));
      if (abort) return abort.apply(this, arguments);
    };
  });
  running.catch(function () { /* each call says it */ });

  function plural(n) { return n + ' argument' + (n === 1 ? '' : 's'); }

  // A value as an error quotes it: JSON, at most 100 characters (a cycle or a BigInt: its type).
  function quoted(value) {
    try { return String(JSON.stringify(value)).slice(0, 100); } catch (e) { return 'a ' + typeof value + ' that is not JSON'; }
  }

  // The request as plain JSON data ({ id, call, args }), or throws Error(what is wrong).
  function checked(data) {
    if (data.swarmlab !== kVersion)
      throw new Error('swarmlab: ' + quoted(data.swarmlab) + ' is not a version of the message format (1 is)');
    var id = data.id;
    if (!((typeof id === 'string' && id.length <= kMaxIdChars) || (typeof id === 'number' && isFinite(id))))
      throw new Error('id must be a string of at most ' + kMaxIdChars + ' characters or a number');
    // A long text is refused before it is copied again.
    if (Array.isArray(data.args) && data.args.some(function (a) { return typeof a === 'string' && a.length > kMaxMessageChars; }))
      throw new Error('the message is over ' + kMaxMessageChars + ' characters of JSON, the limit');
    var text;
    try { text = JSON.stringify(data); } catch (e) { throw new Error('the message is not JSON data (' + e.message.split('\n')[0] + ')'); }
    if (text.length > kMaxMessageChars)
      throw new Error('the message is ' + text.length + ' characters of JSON; at most ' + kMaxMessageChars);
    var plain = JSON.parse(text);  // structured-clone extras (Map, Blob, Date) become JSON's
    var call = plain.call;
    if (typeof call !== 'string' || !Object.prototype.hasOwnProperty.call(calls, call))
      throw new Error((typeof call === 'string' ? 'unknown call ' + quoted(call) : 'call must be a string') +
                      ' (calls: ' + Object.keys(calls).join(', ') + ')');
    var args = plain.args === undefined ? [] : plain.args;
    if (!Array.isArray(args)) throw new Error(call + ': args must be an array');
    var wanted = calls[call];
    if (args.length !== wanted.length)
      throw new Error(call + ' takes ' + plural(wanted.length) + ', not ' + args.length);
    wanted.forEach(function (kind, i) {
      if (!kinds[kind][1](args[i]))
        throw new Error(call + ': argument ' + (i + 1) + ' must be ' + kinds[kind][0] + ', not ' + quoted(args[i]));
    });
    return { id: plain.id, call: call, args: args };
  }

  function run(request) {
    if (request.call === 'ready') return true;
    if (request.call === 'lastMessage') return api.lastMessage;
    return api[request.call].apply(api, request.args);
  }

  var queue = Promise.resolve();
  var warned = {};
  window.addEventListener('message', function (event) {
    var data = event.data;
    if (!data || typeof data !== 'object' || Array.isArray(data) || !('swarmlab' in data)) return;  // not ours
    if (allowed.indexOf(event.origin) < 0) {
      if (!warned[event.origin]) console.warn('swarmlab: a message from ' + event.origin + ' was ignored: not in ?origins=');
      warned[event.origin] = true;
      return;
    }
    var source = event.source, origin = event.origin;
    if (!source || typeof source.postMessage !== 'function') return;
    function reply(message) {
      message.swarmlab = kVersion;
      try {
        source.postMessage(message, origin);
      } catch (e) {  // a result that cannot be cloned; never expected
        source.postMessage({ swarmlab: kVersion, id: message.id, error: 'the reply could not be sent: ' + e.message }, origin);
      }
    }
    var request;
    try {
      request = checked(data);
    } catch (e) {
      var id = data.id;
      reply({ id: (typeof id === 'string' && id.length <= kMaxIdChars) || (typeof id === 'number' && isFinite(id)) ? id : null,
              error: e.message });
      return;
    }
    // The result is wrapped, so that a Promise in it is not waited for before the next call.
    var started = queue.then(function () { return running; })
      .then(function () { return { result: run(request) }; });
    var settled = started.then(function (wrapped) { return wrapped.result; })
      .then(function (result) { reply({ id: request.id, result: result === undefined ? null : result }); },
            function (e) { reply({ id: request.id, error: (e && e.message) || String(e) }); });
    // A seek is answered when it ends (the time reached, or the error when cancelled or
    // refused); the calls after it do not wait for that (a new seek cancels it).
    queue = request.call === 'seek' ? started.then(function () {}, function () {}) : settled;
  });

  // The parent (if any) hears that the app runs, at the allowed origins only: a page of another
  // origin is not told.
  running.then(function () {
    if (window.parent === window) return;
    allowed.forEach(function (origin) {
      window.parent.postMessage({ swarmlab: kVersion, event: 'ready', embed: embedded }, origin);
    });
  }, function () {});
})();
