// Offline use (web/README.md, "Offline"), loaded by the page (shell.html) right after its own
// script, before the app's:
// - registers the service worker (service_worker.js) once the app has drawn its first frame,
//   so that it never competes with the app's own download; the worker caches the app, and
//   from the next visit on the page starts with the network off;
// - says in one line of the loading card, and once in the message line, when the page works
//   offline: the browser says it is offline, or the server could not be reached to look for
//   a new version (the page then came from the browser's saved copy);
// - lets a new version take over once it is cached (the worker waits for the word, so that a
//   page never gets its script from one version and its wasm from another): the next visit
//   runs it and says "Swarm Lab was updated". Nothing here reloads the page.
// It does nothing where service workers are missing: a file:// page, plain http to another
// computer than this one (browsers allow them on https and on localhost only), an old browser.
// Read-only state for pages and tests: window.swarmlabOffline = { version, installed, offline,
// updatedFrom }: the version this page runs (null before a worker controls it), the version
// the next visit will run, whether the offline line shows, the version before an update.
(function () {
  'use strict';
  var OFFLINE_TEXT = 'Offline: running from this browser\u2019s saved copy.';
  var state = window.swarmlabOffline = { version: null, installed: null, offline: false, updatedFrom: null };
  var started = false, pendingNotice = null;

  function notice(text) {
    if (!started) { pendingNotice = pendingNotice || text; return; }
    var box = document.getElementById('notice');
    // A message the app shows (a link that failed, a copied link) matters more.
    if (box && box.hidden && window.Module && Module.showNotice) Module.showNotice('info', text, '');
  }
  function showOffline() {
    if (state.offline) return;
    state.offline = true;
    var line = document.getElementById('offline-line');
    if (line) { line.textContent = OFFLINE_TEXT; line.hidden = false; }
    notice(OFFLINE_TEXT);
  }
  try {
    if (navigator.onLine === false) showOffline();
    window.addEventListener('offline', showOffline);
  } catch (e) { /* nothing to say */ }

  var sw = null;
  try {
    if (/^https?:$/.test(location.protocol) && 'serviceWorker' in navigator) sw = navigator.serviceWorker;
  } catch (e) { sw = null; }

  // The version the worker controlling this page caches (a Promise; null without one).
  function askVersion() {
    var worker = sw.controller;
    if (!worker) return Promise.resolve(null);
    return new Promise(function (resolve) {
      var channel = new MessageChannel();
      channel.port1.onmessage = function (e) { resolve((e.data && e.data.swarmlabVersion) || null); };
      worker.postMessage('version', [channel.port2]);
    });
  }
  function remember(version) {
    var before = null;
    try {
      before = localStorage.getItem('swarmlab.version');
      localStorage.setItem('swarmlab.version', version);
    } catch (e) { /* no storage: no notice */ }
    return before;
  }

  var versionKnown = Promise.resolve();
  if (sw && sw.controller) {
    // This page came through the worker: its version, and whether the server answers.
    versionKnown = askVersion().then(function (version) {
      state.version = state.installed = version;
      var before = version && remember(version);
      if (before && before !== version) {
        state.updatedFrom = before;
        notice('Swarm Lab was updated.');
      }
    });
    if (!state.offline)
      sw.getRegistration().then(function (reg) { return reg && reg.update(); })
        .catch(function () { showOffline(); });
  }

  function register() {
    if (!sw) return;
    sw.register('service_worker.js').then(function (reg) {
      return versionKnown.then(function () {
        // A worker installed for a new version: this page's own files are loaded (the first
        // frame is drawn), so it may take over; the next visit runs it.
        function offer(worker) {
          if (worker && sw.controller) worker.postMessage('activate');
        }
        function watch(worker) {
          if (!worker) return;
          worker.addEventListener('statechange', function () { if (worker.state === 'installed') offer(worker); });
        }
        offer(reg.waiting);
        watch(reg.installing);
        reg.addEventListener('updatefound', function () { watch(reg.installing); });
      });
    }).catch(function (e) { console.warn('Swarm Lab works online only here: ' + e); });
    sw.addEventListener('controllerchange', function () {
      askVersion().then(function (version) {
        state.installed = version;
        if (state.version === null) {  // the first visit: the worker took this page over
          state.version = version;
          if (version) remember(version);
        }
      });
    });
  }

  function appStarted() {
    started = true;
    if (pendingNotice) notice(pendingNotice);
    try { register(); } catch (e) { /* online only */ }
  }
  var first = window.Module && Module.onFirstFrame;
  if (window.Module) Module.onFirstFrame = function () {
    if (first) first.apply(this, arguments);
    appStarted();
  };
  // The app's script loads beside this one (shell.html starts it first): on a slow or busy
  // machine its first frame may come before this script does.
  if (window.swarmlab && window.swarmlab.firstFrameMs !== null) appStarted();
})();
