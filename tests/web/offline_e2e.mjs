// Offline and installable (web/README.md, "Offline"): after one visit the page starts with the
// network off, says so in one line, and a lesson opens and runs, pressed by a person (the
// parallel DOM's roles and names, real mouse events); the manifest and its icons are what an
// install needs; a new version reaches the next visit and says "Swarm Lab was updated"; a
// failed update leaves the cached version working. The suite serves build/web itself (a small
// node server), so it can go down (the network off), hand the browser a changed service
// worker (a new version, without a rebuild: the worker's VERSION with "-next" appended), or
// fail every file but the worker (an update that cannot be fetched). Every wait is on a
// condition, save the minute Chromium takes to start a new version's worker beside the app
// (step 4). Screenshots of the loading card and the app offline at a laptop's and a phone's
// size go to build/web-test/.
import { createServer } from 'node:http';
import { readFileSync, existsSync, statSync, mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, extname, normalize } from 'node:path';
import { chromium } from 'playwright-core';
import * as harness from './harness.mjs';
import { person } from './person.mjs';

const { root, webDir, outDir, chromiumPath, check, runSuite, clockAdvances, pageErrors, consoleErrors, watch, freePort,
        published } = harness;

const OFFLINE_TEXT = 'Offline: running from this browser\u2019s saved copy.';
const PROBE = 'fonts/offline-e2e-probe.txt';  // a file fetched on demand, as a font subset is
// The Chinese font as an older build published it (another content, another hash in its name).
const OLD_FONT = 'fonts/noto-sans-sc-subset.00000000.otf';
const TYPES = { '.html': 'text/html; charset=utf-8', '.js': 'text/javascript', '.wasm': 'application/wasm',
                '.png': 'image/png', '.svg': 'image/svg+xml', '.webmanifest': 'application/manifest+json',
                '.json': 'application/json', '.txt': 'text/plain', '.woff2': 'font/woff2' };

// The site as the browser sees it: build/web, and what the suite makes of it.
const site = { url: '', down: false, suffix: '', failFiles: false, served: [], refused: 0 };
async function startSite() {
  const server = createServer((req, res) => {
    if (site.down) { site.refused++; req.socket.destroy(); return; }
    const path = decodeURIComponent(new URL(req.url, 'http://x').pathname).replace(/^\/+/, '') || 'index.html';
    site.served.push(path);
    if (site.failFiles && path !== 'service_worker.js') { res.writeHead(503); res.end(); return; }
    let body, modified = new Date(0);
    if (path === PROBE) body = Buffer.from('probe');
    else if (path === OLD_FONT) body = Buffer.from('an older build\'s font');
    else {
      const file = normalize(join(webDir, path));
      if (!file.startsWith(webDir) || !existsSync(file) || !statSync(file).isFile()) { res.writeHead(404); res.end(); return; }
      body = readFileSync(file);
      modified = statSync(file).mtime;
      if (path === 'service_worker.js' && site.suffix)
        body = Buffer.from(body.toString().replace(/const VERSION = '([^']*)'/, `const VERSION = '$1${site.suffix}'`));
    }
    res.writeHead(200, { 'Content-Type': TYPES[extname(path)] || 'application/octet-stream',
                         'Content-Length': body.length, 'Last-Modified': modified.toUTCString() });
    res.end(body);
  });
  const port = await freePort();
  await new Promise((r) => server.listen(port, '127.0.0.1', r));
  return { server, url: `http://127.0.0.1:${port}/` };
}

// The browser, on a profile of its own (the worker and its cache live there), with
// harness.launchBrowser's flags.
const profile = mkdtempSync(join(tmpdir(), 'swarmlab-offline-'));
let context = null;
async function openBrowser() {
  context = await chromium.launchPersistentContext(profile, {
    executablePath: chromiumPath, headless: true, viewport: { width: 1280, height: 720 }, timeout: 30_000,
    args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
           '--disable-component-update', '--disable-sync', '--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
  });
  context.setDefaultTimeout(30_000);
  const page = context.pages()[0] || await context.newPage();
  await page.addInitScript(recordNotices);
  await page.addInitScript(() => {  // a returning student (harness.openApp): no welcome
    if (!localStorage.getItem('swarmlab.progress'))
      localStorage.setItem('swarmlab.progress', JSON.stringify({ version: 1, welcomed: true }));
  });
  watch(page, 'offline');
  return page;
}

// Every message the page's message line showed (it hides them again after 12 s).
function recordNotices() {
  window.noticesShown = [];
  document.addEventListener('DOMContentLoaded', () => {
    const text = document.getElementById('notice-text');
    new MutationObserver(() => window.noticesShown.push(text.textContent)).observe(text, { childList: true, characterData: true, subtree: true });
  });
}

// A visit: the page loaded again (a reload keeps the tab, as a person's does), until the app
// draws its first frame or says why not.
async function visit(page) {
  if (page.url().startsWith(site.url)) await page.reload({ waitUntil: 'load' });
  else await page.goto(site.url, { waitUntil: 'load' });  // a browser opened again
  return page.waitForFunction(() => window.swarmlabError || (window.swarmlab && window.swarmlab.firstFrameMs !== null),
                              null, { timeout: 30_000 })
    .then(() => page.evaluate(() => window.swarmlabError || ''), (e) => String(e));
}

const offlineState = (page) => page.evaluate(() => ({ ...window.swarmlabOffline, onLine: navigator.onLine }));
const cached = (page) => page.evaluate(async () => {
  const out = {};
  for (const name of await caches.keys())
    out[name] = (await (await caches.open(name)).keys()).map((r) => new URL(r.url).pathname.replace(/^\//, '')).sort();
  return out;
});
// The width and height in a PNG's header.
function pngSize(file) {
  const b = readFileSync(file);
  return b.toString('ascii', 1, 4) === 'PNG' ? [b.readUInt32BE(16), b.readUInt32BE(20)] : null;
}

// The loading card as it was (the app hides it at its first frame), and the app, at a laptop's
// and a phone's size.
async function screenshots(page, what) {
  for (const [w, h] of [[1280, 720], [390, 844]]) {
    await page.setViewportSize({ width: w, height: h });
    await page.waitForFunction(([w, h]) => {
      const s = window.swarmlab.state();
      return s.display.width === w && s.display.height === h && s.layout_settled;
    }, [w, h], { timeout: 20_000 });
    await page.screenshot({ path: join(outDir, `offline-${what}-app-${w}x${h}.png`) });
    await page.evaluate(() => document.getElementById('overlay').classList.remove('hidden'));
    await page.waitForFunction(() => getComputedStyle(document.getElementById('overlay')).opacity === '1');
    await page.screenshot({ path: join(outDir, `offline-${what}-loading-${w}x${h}.png`) });
    await page.evaluate(() => document.getElementById('overlay').classList.add('hidden'));
    await page.waitForFunction(() => getComputedStyle(document.getElementById('overlay')).opacity === '0');
  }
  await page.setViewportSize({ width: 1280, height: 720 });
  console.log(`      screenshots -> build/web-test/offline-${what}-{app,loading}-{1280x720,390x844}.png`);
}

async function main() {
  const { server, url } = await startSite();
  site.url = url;
  try {
    let page = await openBrowser();

    // 1. The first visit: the app starts from the network, and a service worker caches it.
    await page.goto(url, { waitUntil: 'load' });
    const firstFrame = await page.waitForFunction(() => window.swarmlabError || (window.swarmlab && window.swarmlab.firstFrameMs !== null),
                                                  null, { timeout: 30_000 }).then(() => true, () => false);
    if (!check('the first visit starts the app', firstFrame && !(await page.evaluate(() => window.swarmlabError)))) return;
    const t0 = Date.now();
    // The worker fetches every file of the version before it takes over, at the browser's
    // background priority: on a loaded machine that may take a minute.
    const controlled = await page.waitForFunction(() => navigator.serviceWorker.controller !== null &&
                                                  window.swarmlabOffline.version !== null, null, { timeout: 90_000 })
      .then(() => true, () => false);
    let st = await offlineState(page);
    // Where it stood, if it did not take over: the registration's workers and what was fetched.
    const worker = controlled ? '' : await page.evaluate(async () => {
      const reg = await navigator.serviceWorker.getRegistration();
      if (!reg) return 'no registration';
      return ['installing', 'waiting', 'active'].map((k) => `${k} ${reg[k] ? reg[k].state : '-'}`).join(', ');
    }).catch((e) => String(e));
    check('a service worker controls the page after the first visit', controlled,
          `version ${st.version}, after ${Date.now() - t0} ms` +
          (controlled ? '' : `; ${worker}; served ${site.served.length} files, service_worker.js ${site.served.includes('service_worker.js') ? 'fetched' : 'never fetched'}`));
    const v1 = st.version;
    check('online, the page does not say it is offline', st.offline === false && st.onLine === true);
    const probe = await page.evaluate((p) => fetch(p).then((r) => r.text()), PROBE);
    await page.evaluate((p) => fetch(p).then((r) => r.text()), OLD_FONT);
    let caches1 = await cached(page);
    const files = caches1[`swarmlab-${v1}`] || [];
    // By the names the build published them under (with their content's hash).
    const wanted = ['index.html', 'manifest.webmanifest',
                    ...['swarmlab.js', 'swarmlab.wasm', 'offline.js', 'icon-192.png', 'icon-512.png'].map(published)];
    check('the cache holds the page, its script, its wasm, the manifest and the icons, keyed on the version',
          Object.keys(caches1).length === 1 && wanted.every((f) => f && files.includes(f)), JSON.stringify(caches1));
    check('a file fetched on demand (fonts/...) goes into the cache when first fetched',
          probe === 'probe' && files.includes(PROBE), files.join(', '));

    // 2. The manifest and icons an install needs.
    const manifestHref = await page.evaluate(() => document.querySelector('link[rel=manifest]')?.getAttribute('href'));
    const manifest = JSON.parse(readFileSync(join(webDir, 'manifest.webmanifest'), 'utf8'));
    const background = await page.evaluate(() => getComputedStyle(document.body).backgroundColor);
    const hex = (c) => '#' + c.match(/\d+/g).slice(0, 3).map((n) => Number(n).toString(16).padStart(2, '0')).join('');
    check('the page links the manifest', manifestHref === 'manifest.webmanifest', String(manifestHref));
    check('the manifest names the app, starts it standalone in its folder, in the page\'s colours',
          manifest.name === 'Swarm Lab' && manifest.short_name && manifest.start_url === './' && manifest.display === 'standalone' &&
          manifest.background_color === hex(background) && manifest.theme_color === hex(background),
          `${JSON.stringify({ ...manifest, icons: undefined })}, page ${hex(background)}`);
    const icons = manifest.icons.map((i) => ({ ...i, size: pngSize(join(webDir, i.src)) }));
    for (const s of [192, 512])
      check(`a ${s}x${s} PNG icon, as any and as maskable`,
            ['any', 'maskable'].every((p) => icons.some((i) => i.purpose === p && i.sizes === `${s}x${s}` && i.type === 'image/png' &&
                                                                 i.size && i.size[0] === s && i.size[1] === s)),
            JSON.stringify(icons.filter((i) => i.sizes === `${s}x${s}`).map((i) => [i.src, i.purpose, i.size])));

    // 3. The network off: the page starts from the cache, says so, and a lesson runs.
    let error = '';
    site.down = true;
    await context.setOffline(true);
    const servedBefore = site.served.length;
    error = await visit(page);
    check('offline, the app starts', error === '', error);
    st = await offlineState(page);
    const line = await page.evaluate(() => { const l = document.getElementById('offline-line'); return l.hidden ? '' : l.textContent; });
    check('offline, the loading card says so in one line', line === OFFLINE_TEXT && st.offline, `"${line}", onLine ${st.onLine}`);
    await page.waitForFunction((t) => window.noticesShown.includes(t), OFFLINE_TEXT, { timeout: 10_000 }).catch(() => {});
    check('and the message line says it once the app runs', (await page.evaluate(() => window.noticesShown)).includes(OFFLINE_TEXT),
          JSON.stringify(await page.evaluate(() => window.noticesShown)));
    check('a file fetched on demand before comes from the cache offline',
          (await page.evaluate((p) => fetch(p).then((r) => r.text(), (e) => String(e)), PROBE)) === 'probe');
    const me = person(page, 'mouse');
    const lessonFile = JSON.parse(readFileSync(join(root, 'assets/lessons/01-one-period.json'), 'utf8'));
    await me.press('menuitem', 'Lessons');
    await me.press('menuitem', lessonFile.title);
    const opened = await me.dom.getByText(`Step 1 of ${lessonFile.steps.length}`, { exact: false }).first()
      .waitFor({ state: 'attached', timeout: 20_000 }).then(() => true, () => false);
    check('offline, a lesson opens from the Lessons menu', opened &&
          (await page.evaluate(() => window.swarmlab.lessonState()?.id)) === lessonFile.id);
    if (!(await me.find('button', /Pause/).count())) await me.press('button', /Play/);
    const runs = await clockAdvances(page);
    check('offline, the lesson\'s run plays', runs.ok, runs.detail);
    await me.press('button', /^Next \u2192/);
    const next = await me.dom.getByText(`Step 2 of ${lessonFile.steps.length}`, { exact: false }).first()
      .waitFor({ state: 'attached', timeout: 20_000 }).then(() => true, () => false);
    check('offline, Next goes to the lesson\'s second step', next);
    check('offline, nothing reached the server', site.served.length === servedBefore,
          `${site.served.length - servedBefore} requests served, ${site.refused} refused`);
    await screenshots(page, 'offline');

    // 4. Back online, a new version: the next visit fetches it and it takes over the cache;
    // the visit after that runs it and says so.
    site.down = false;
    await context.setOffline(false);
    site.suffix = '-next';
    const mark = site.served.length;
    error = await visit(page);
    check('online again, the app starts', error === '', error);
    // Chromium starts the new worker about a minute after the visit asks for it while the app
    // draws its frames with a software renderer (54-58 s measured here, the same beside a
    // page that only spins 14 ms a frame; 2.6 s beside one that spins 1 ms); later checks in
    // the same session take milliseconds. A real GPU leaves the page's main thread idle.
    const asked = Date.now();
    let took = await page.waitForFunction((v) => window.swarmlabOffline.installed === v + '-next', v1, { timeout: 100_000 })
      .then(() => true, () => false);
    const tookMs = Date.now() - asked;
    // The new worker deletes the old cache as it activates, just after it takes the page over.
    took = took && await page.evaluate(async (name) => {
      for (const deadline = Date.now() + 20_000; Date.now() < deadline; await new Promise((r) => setTimeout(r, 50)))
        if ((await caches.keys()).join() === name) return true;
      return false;
    }, `swarmlab-${v1}-next`);
    const caches2 = await cached(page);
    st = await offlineState(page);
    check('a new version is fetched on the next visit and replaces the cached one', took &&
          Object.keys(caches2).join() === `swarmlab-${v1}-next` && caches2[`swarmlab-${v1}-next`].includes(published('swarmlab.wasm')),
          `installed ${st.installed} ${tookMs} ms after the visit, caches ${JSON.stringify(Object.keys(caches2))}`);
    check('the page that fetched it runs on unchanged, without a notice', st.version === v1 && st.offline === false &&
          !(await page.evaluate(() => window.noticesShown.some((t) => /updated/.test(t)))));
    check('a file fetched on demand is carried into the new version\'s cache', (caches2[`swarmlab-${v1}-next`] || []).includes(PROBE));
    const font = published('fonts/noto-sans-sc-subset.otf');
    check('a font fetched under an older build\'s name is fetched again under this build\'s, the old one left behind',
          (caches1[`swarmlab-${v1}`] || []).includes(OLD_FONT) &&
          (caches2[`swarmlab-${v1}-next`] || []).includes(font) && !caches2[`swarmlab-${v1}-next`].includes(OLD_FONT),
          `${font}; before ${(caches1[`swarmlab-${v1}`] || []).filter((f) => f.startsWith('fonts/'))}, after ${(caches2[`swarmlab-${v1}-next`] || []).filter((f) => f.startsWith('fonts/'))}`);
    error = await visit(page);
    await page.waitForFunction(() => window.noticesShown.includes('Swarm Lab was updated.'), null, { timeout: 10_000 }).catch(() => {});
    st = await offlineState(page);
    check('the visit after runs the new version and says "Swarm Lab was updated."', error === '' &&
          st.version === v1 + '-next' && st.updatedFrom === v1 &&
          (await page.evaluate(() => window.noticesShown)).includes('Swarm Lab was updated.'),
          `${error} ${JSON.stringify(st)}, notices ${JSON.stringify(await page.evaluate(() => window.noticesShown))}`);
    error = await visit(page);
    check('and says it once: the visit after that does not', error === '' &&
          !(await page.evaluate(() => window.noticesShown.some((t) => /updated/.test(t)))));

    // 5. An update that cannot be fetched (every file but the worker fails): the cached version
    // goes on working.
    site.suffix = '-broken';
    site.failFiles = true;
    error = await visit(page);
    check('while an update fails, the app starts from the cache', error === '', error);
    const attempt = await page.evaluate(async () => {
      const reg = await navigator.serviceWorker.getRegistration();
      await reg.update().catch(() => {});
      const w = reg.installing || reg.waiting;
      if (!w) return 'no new worker left';
      if (w.state === 'redundant') return 'redundant';
      return new Promise((res) => w.addEventListener('statechange', () => {
        if (w.state !== 'installing') res(w.state);
      }));
    });
    const caches3 = await cached(page);
    check('the failed update is dropped and the cached version kept',
          (attempt === 'redundant' || attempt === 'no new worker left') && Object.keys(caches3).join() === `swarmlab-${v1}-next`,
          `new worker: ${attempt}, caches ${JSON.stringify(Object.keys(caches3))}`);
    error = await visit(page);
    st = await offlineState(page);
    const runs2 = await clockAdvances(page);
    check('the next visit still runs the cached version', error === '' && st.version === v1 + '-next' && runs2.ok,
          `${error} version ${st.version}, ${runs2.detail}`);

    check('no page errors', pageErrors.length === 0, pageErrors.join(' | '));
    // The refused and failed requests of steps 3 and 5 are the point; anything else is not.
    const unexpected = consoleErrors.filter((e) => !/HTTP 503|ERR_INTERNET_DISCONNECTED|Failed to update a ServiceWorker|works online only/.test(e));
    check('no other console errors', unexpected.length === 0, unexpected.join(' | '));
  } finally {
    if (context) await context.close().catch(() => {});
    rmSync(profile, { recursive: true, force: true });
    server.close();
  }
}

await runSuite('offline_e2e', 140_000, main);
