// Swarm Lab's service worker: after one visit the app starts and works with the network off.
// The build writes build/web/service_worker.js from this file (web/publish.py) with VERSION, a
// hash of every file it published, FILES, the files the page loads, and ON_DEMAND, those it
// fetches only when needed (a language's font), by their published names (with their
// content's hash). A changed build is a changed worker script, which the browser notices at
// the next visit (it checks the script at every page load); web/offline.js on the page does
// the rest.
//
// - install: every file of this version goes into the cache "swarmlab-VERSION", fetched past
//   the HTTP cache, save those whose name carries their content's hash (any copy of them is
//   the right one). One file missing fails the install: the version already cached stays.
// - fetch: what the cache holds is answered from it (cache first: the page, its script and its
//   wasm always come from one version); anything else of this site goes to the network and,
//   when it arrives whole, into the cache too (the fonts a language fetches on demand, under
//   fonts/), so that what a visit used works offline afterwards.
// - an update waits until the page says it is safe (offline.js posts 'activate' once its own
//   files are loaded), then takes over and deletes the caches of older versions, after
//   copying into its own cache what those fetched on demand (again from the network when it
//   can, else the old copy), so that a chosen language's fonts stay offline. A file of the app
//   that this version publishes under a new name (its content changed) is fetched under that
//   name instead; the old one is left behind.
'use strict';
const VERSION = '@SWARMLAB_WEB_VERSION@';
const FILES = [@SWARMLAB_WEB_FILES@];
const ON_DEMAND = [@SWARMLAB_WEB_ON_DEMAND@];
const PREFIX = 'swarmlab-';
const CACHE = PREFIX + VERSION;

// An address relative to this worker's folder (the app's folder), as the cache keys it.
const here = (path) => new URL(path, self.registration.scope).href;

// A published name without its content's hash: fonts/x.1a2b3c4d.otf -> fonts/x.otf.
const unhashed = (url) => url.replace(/\.[0-9a-f]{8}(\.[^./]+)$/, '$1');

async function carryOver(cache) {
  const precached = new Set(FILES.map(here));
  const renamed = new Map(ON_DEMAND.map((f) => [unhashed(here(f)), here(f)]));
  for (const name of await caches.keys()) {
    if (!name.startsWith(PREFIX) || name === CACHE) continue;
    const old = await caches.open(name);
    for (const request of await old.keys()) {
      const url = renamed.get(unhashed(request.url)) || request.url;
      if (precached.has(url) || (await cache.match(url))) continue;
      try {
        const fresh = await fetch(url, { cache: 'reload' });
        if (fresh.ok && fresh.status === 200) { await cache.put(url, fresh); continue; }
      } catch { /* offline: the old copy */ }
      const kept = url === request.url && (await old.match(request));
      if (kept) await cache.put(url, kept);
    }
  }
}

self.addEventListener('install', (event) => {
  event.waitUntil((async () => {
    const cache = await caches.open(CACHE);
    try {
      // A name with its content's hash may come from the HTTP cache (the page has just
      // downloaded it: not twice); the page and the manifest come from the server.
      await cache.addAll(FILES.map((f) => new Request(here(f), { cache: unhashed(f) === f ? 'reload' : 'default' })));
    } catch (e) {
      await caches.delete(CACHE);  // half a version is no version
      throw e;
    }
    await carryOver(cache);
  })());
});

self.addEventListener('activate', (event) => {
  event.waitUntil((async () => {
    for (const name of await caches.keys())
      if (name.startsWith(PREFIX) && name !== CACHE) await caches.delete(name);
    await self.clients.claim();  // the first visit's page too: it works offline from now on
  })());
});

self.addEventListener('message', (event) => {
  // 'version' comes with a port to answer on (offline.js, askVersion).
  if (event.data === 'version' && event.ports[0]) event.ports[0].postMessage({ swarmlabVersion: VERSION });
  else if (event.data === 'activate') self.skipWaiting();
});

self.addEventListener('fetch', (event) => {
  const request = event.request;
  if (request.method !== 'GET' || !request.url.startsWith(self.registration.scope)) return;
  event.respondWith((async () => {
    const cache = await caches.open(CACHE);
    // A visit (the app's folder or its index.html, with ?welcome or a #preset=... or not)
    // gets the cached page.
    const path = new URL(request.url).pathname;
    const page = request.mode === 'navigate' && (path.endsWith('/') || path.endsWith('/index.html'));
    const key = page ? here('index.html') : request;
    const cached = await cache.match(key, { ignoreSearch: true });
    if (cached) return cached;
    const response = await fetch(request);
    if (response.ok && response.status === 200 && response.type === 'basic')
      await cache.put(request.url.split('?')[0], response.clone());
    return response;
  })());
});
