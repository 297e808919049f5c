// What every browser suite in tests/web/ shares: the served build/web, one headless Chromium
// with a persistent profile, pages that report their errors, screenshots measured by colour,
// clicks, the CLI's validation message, and the "N passed, M failed in S s" line (each check's
// line ends with the seconds since the suite started). Every wait is on a condition (the
// state an action should produce), never on a frame count or a sleep. A suite calls
// runSuite(name, stallMs, main) with main(url) doing its checks.
import { chromium } from 'playwright-core';
import { spawn, spawnSync } from 'node:child_process';
import { mkdtempSync, mkdirSync, rmSync, existsSync, writeFileSync, readFileSync } from 'node:fs';
import { createServer } from 'node:net';
import { tmpdir } from 'node:os';
import { join, dirname, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

export const root = resolve(dirname(fileURLToPath(import.meta.url)), '../..');
export const webDir = process.env.SWARMLAB_WEB_DIR || join(root, 'build/web');
export const outDir = join(root, 'build/web-test');
export const chromiumPath = process.env.CHROMIUM || '/usr/bin/chromium';
// The native CLI, to compare validation messages with (skipped when it is not built).
export const cliPath = process.env.SWARMLAB_CLI || join(root, 'build/app/swarmlab');
export const WASM_LIMIT = 4 * 1024 * 1024;
/** The name under which the build published a file that changes with a build (web/publish.py):
 *  'swarmlab.wasm' is 'swarmlab.3f2a9c1b.wasm', with its content's hash, as index.html names it
 *  (window.swarmlabFiles); undefined for a name it does not know. */
export function published(name) {
  const page = readFileSync(join(webDir, 'index.html'), 'utf8');
  const map = page.match(/window\.swarmlabFiles = (\{[^}]*\});/);
  return map ? JSON.parse(map[1])[name] : undefined;
}
export const START_LIMIT_MS = 3000;  // navigation start to the first frame
export const DEFAULT_PRESET = 'Four masses (paper Fig. 1)';

export let passed = 0, failed = 0;
const suiteStart = Date.now();
// Each line ends with the seconds since the suite started, so that a slow suite's log says
// where its time went.
const since = () => ` [${((Date.now() - suiteStart) / 1000).toFixed(1)} s]`;
// When the last check was made: the suite's watchdog measures a stall from there (runSuite).
let lastProgress = Date.now();
export function check(name, ok, detail = '') {
  lastProgress = Date.now();
  if (ok) { passed++; console.log(`ok    ${name}${detail ? ' (' + detail + ')' : ''}${since()}`); }
  else { failed++; console.log(`FAIL  ${name}${detail ? ': ' + detail : ''}${since()}`); }
  return ok;
}
export const sleep = (ms) => new Promise((r) => setTimeout(r, ms));
export const base64url = (buf) => Buffer.from(buf).toString('base64').replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
export const shipped = (file) => JSON.parse(readFileSync(join(root, 'assets/presets', file), 'utf8'));

let server = null, profile = null;
/** The browser of the running suite (set by runSuite). */
export let context = null;
/** Closes the suite's browser (its profile too), keeping the server: a suite may open another. */
export async function closeBrowser() {
  if (context) await context.close().catch(() => {});
  context = null;
  if (profile) rmSync(profile, { recursive: true, force: true });
  profile = null;
}
export async function cleanup() {
  if (context) await context.close().catch(() => {});
  context = null;
  if (server && server.exitCode === null) server.kill('SIGTERM');
  if (profile) rmSync(profile, { recursive: true, force: true });
}
export function finish() {
  console.log(`${passed} passed, ${failed} failed in ${((Date.now() - suiteStart) / 1000).toFixed(1)} s`);
  process.exit(failed > 0 || passed === 0 ? 1 : 0);
}

export function freePort() {
  return new Promise((res, rej) => {
    const s = createServer();
    s.once('error', rej);
    s.listen(0, '127.0.0.1', () => { const { port } = s.address(); s.close(() => res(port)); });
  });
}

export async function startServer() {
  const port = await freePort();
  server = spawn('python3', ['-m', 'http.server', '--bind', '127.0.0.1', '--directory', webDir, String(port)],
                 { stdio: ['ignore', 'ignore', 'ignore'] });
  const url = `http://127.0.0.1:${port}/`;
  const deadline = Date.now() + 30_000;  // a loaded machine starts python slowly
  while (Date.now() < deadline) {
    if (server.exitCode !== null) throw new Error('http.server exited with ' + server.exitCode);
    try { if ((await fetch(url)).ok) return url; } catch { /* not up yet */ }
    await sleep(100);
  }
  throw new Error('http.server did not answer on ' + url);
}

/** build/web served as a class gets it: scripts/web.sh --no-build (caddy with
 *  web/serve/Caddyfile: compressed copies, cache headers) on a free loopback port. */
export async function startWebServer() {
  const port = await freePort();
  server = spawn(join(root, 'scripts/web.sh'), ['--no-build', '--port', String(port)], { stdio: ['ignore', 'ignore', 'pipe'] });
  let said = '';
  server.stderr.on('data', (d) => { said += d; });
  const url = `http://127.0.0.1:${port}/`;
  const deadline = Date.now() + 30_000;
  while (Date.now() < deadline) {
    if (server.exitCode !== null) throw new Error(`scripts/web.sh exited with ${server.exitCode}: ${said.trim()}`);
    try { if ((await fetch(url)).ok) return url; } catch { /* not up yet */ }
    await sleep(100);
  }
  throw new Error('scripts/web.sh did not answer on ' + url);
}

// Console errors and uncaught exceptions of every page, checked at the end.
export const pageErrors = [], consoleErrors = [], consoleLog = [];
export function watch(page, label) {
  page.on('pageerror', (e) => pageErrors.push(`${label}: ${e}`));
  page.on('response', (r) => { if (r.status() >= 400) consoleErrors.push(`${label}: HTTP ${r.status()} for ${r.url()}`); });
  page.on('console', (m) => {
    consoleLog.push(`[${label} ${m.type()}] ${m.text()}`);
    if (m.type() === 'error' && !/^Failed to load resource/.test(m.text())) consoleErrors.push(`${label}: ${m.text()}`);
  });
}

// Opens url in a new page and waits until the app has drawn its first frame (or the page
// reports its error). The app treats a test like a person: a first visit shows the welcome. A
// page whose address does not ask for a first visit (?welcome) starts as a returning
// student's, whose progress says the welcome was seen (unless the browser already holds
// progress). `init` runs in the page before its own scripts (as page.addInitScript), e.g. to
// listen to the live region from the start.
export async function openApp(url, label, init = null) {
  const page = await context.newPage();
  if (init) await page.addInitScript(init);
  if (!/[?&]welcome/.test(url))
    await page.addInitScript(() => {
      try {
        if (!localStorage.getItem('swarmlab.progress'))
          localStorage.setItem('swarmlab.progress', JSON.stringify({ version: 1, welcomed: true }));
      } catch { /* no storage: the welcome shows, as for a person */ }
    });
  watch(page, label);
  await page.goto(url, { waitUntil: 'load' });
  let started = true;
  try {
    await page.waitForFunction(() => window.swarmlabError || (window.swarmlab && window.swarmlab.firstFrameMs !== null),
                               null, { timeout: 30_000 });
  } catch { started = false; }
  const error = await page.evaluate(() => window.swarmlabError || null);
  return { page, started: started && !error, error };
}

/** Waits until fn(swarmlab.state(), arg) holds in the page (a lasting state: a window closed,
 *  a menu open, the layout settled), or gives up after 20 s; returns the state it saw last, for
 *  the check after it to judge and report. fn runs in the page: what it needs from here comes in
 *  arg. */
export async function until(page, fn, arg = null) {
  try {
    // A function made here: the page's CSP refuses the eval a predicate given as text needs.
    await page.waitForFunction(new Function('arg', `return (${fn})(window.swarmlab.state(), arg);`), arg,
                               { timeout: 20_000, polling: 'raf' });
  } catch { /* the check after it reports what was seen */ }
  return page.evaluate(() => window.swarmlab.state());
}

/** Runs in the page before its scripts (pass it to openApp as `(${recordLiveRegion})();`):
 *  every text the live region (#announcer) takes, in window.liveRegionSaid. */
export function recordLiveRegion() {
  window.liveRegionSaid = [];
  new MutationObserver((_, waiting) => {
    const region = document.getElementById('announcer');
    if (!region) return;
    new MutationObserver(() => window.liveRegionSaid.push(region.textContent.trim()))
      .observe(region, { childList: true, characterData: true, subtree: true });
    waiting.disconnect();
  }).observe(document, { childList: true, subtree: true });
}

/** Chrome's own counts for the page (DevTools Protocol Performance.getMetrics, after
 *  Performance.enable on `cdp`) by name: TaskDuration, ThreadTime, ScriptDuration, Timestamp... */
export async function pageMetrics(cdp) {
  return Object.fromEntries((await cdp.send('Performance.getMetrics')).metrics.map((m) => [m.name, m.value]));
}

export const state = (page) => page.evaluate(() => {
  const notice = document.getElementById('notice'), text = document.getElementById('notice-text');
  let preset = null;
  try { preset = JSON.parse(window.swarmlab.preset()); } catch { /* not started */ }
  return { time: window.swarmlab.time(), preset, notice: notice.hidden ? '' : text.textContent.trim(),
           noticeKind: notice.className, hash: location.hash };
});

// The app keeps drawing: `n` more frames within limitMs (a loaded machine may draw only a
// few a second), or its frame loop went to sleep with nothing left to change (web/frame_sleep.h):
// either way the loop is alive and has not stalled. A measurement: it reports how long it took.
export async function keepsDrawing(page, n = 3, limitMs = 20_000) {
  const f1 = await page.evaluate(() => window.swarmlab.frames());
  const start = Date.now();
  const ok = await page.waitForFunction((target) => window.swarmlab.frames() >= target || window.swarmlab.sleeping(),
                                        f1 + n, { timeout: limitMs }).then(() => true, () => false);
  const ms = Date.now() - start;
  const { frames, asleep } = await page.evaluate(() => ({ frames: window.swarmlab.frames(), asleep: window.swarmlab.sleeping() }));
  const drew = `${frames - f1} frames in ${ms} ms${asleep ? ', then asleep (nothing to change)' : ''}`;
  return { ok, ms, frames: frames - f1, detail: ok ? drew : `neither ${n} frames nor asleep in ${ms} ms (${drew})` };
}

// The simulated clock moves on: time() passes its value now within 30 s, however slowly a
// loaded machine draws.
export async function clockAdvances(page) {
  const t1 = await page.evaluate(() => window.swarmlab.time());
  const start = Date.now();
  const ok = await page.waitForFunction((t) => window.swarmlab.time() > t, t1, { timeout: 30_000 })
    .then(() => true, () => false);
  const t2 = await page.evaluate(() => window.swarmlab.time());
  return { ok, detail: `t ${t1.toFixed(3)} -> ${t2.toFixed(3)} in ${Date.now() - start} ms` };
}

// The simulated clock stands still while the app keeps drawing (three frames, or asleep).
export async function clockStands(page) {
  const t1 = await page.evaluate(() => window.swarmlab.time());
  const drawn = await keepsDrawing(page);
  const t2 = await page.evaluate(() => window.swarmlab.time());
  return { ok: drawn.ok && t2 === t1, detail: `t ${t1.toFixed(3)} -> ${t2.toFixed(3)} over ${drawn.detail}` };
}

// Decodes a PNG in a blank page and measures it: distinct colours (quantised to 4 bits per
// channel), the share of the most common colour and of black, and in each named rectangle the
// number of vivid pixels (clearly coloured: the particles' colour map, the plot lines; the
// UI's greys, dark blues and white text are not).
export async function analysePng(png, rects = {}) {
  const scratch = await context.newPage();
  await scratch.setContent('<html><body></body></html>');
  const out = await scratch.evaluate(async ({ b64, rects }) => {
    const img = new Image();
    img.src = 'data:image/png;base64,' + b64;
    await img.decode();
    const c = document.createElement('canvas');
    c.width = img.width; c.height = img.height;
    const g = c.getContext('2d');
    g.drawImage(img, 0, 0);
    const d = g.getImageData(0, 0, c.width, c.height).data;
    const counts = new Map();
    let black = 0;
    for (let i = 0; i < d.length; i += 4) {
      const key = ((d[i] >> 4) << 8) | ((d[i + 1] >> 4) << 4) | (d[i + 2] >> 4);
      counts.set(key, (counts.get(key) || 0) + 1);
      if (d[i] < 8 && d[i + 1] < 8 && d[i + 2] < 8) black++;
    }
    const n = d.length / 4;
    let top = 0, topKey = 0;
    for (const [k, v] of counts) if (v > top) { top = v; topKey = k; }
    const vivid = {};
    for (const [name, [x0, y0, x1, y1]] of Object.entries(rects)) {
      let count = 0;
      for (let y = y0; y < y1; ++y) for (let x = x0; x < x1; ++x) {
        const i = 4 * (y * c.width + x);
        const hi = Math.max(d[i], d[i + 1], d[i + 2]), lo = Math.min(d[i], d[i + 1], d[i + 2]);
        if (hi >= 150 && hi - lo >= 90) count++;
      }
      vivid[name] = count;
    }
    return { width: c.width, height: c.height, distinct: counts.size, topShare: top / n,
             topColor: '#' + topKey.toString(16).padStart(3, '0'), blackShare: black / n, vivid };
  }, { b64: png.toString('base64'), rects });
  await scratch.close();
  return out;
}

// At 1280x720 and UI scale 1: the controls take the left 352 px, the plots the right 400 px
// (app/desktop/app.cpp), the menu bar the top 24 px; the transport bar and the read-outs sit in
// the top left corner of the 3D view, and the page's messages at its bottom.
export const VIEW_RECTS = { viewRight: [580, 40, 870, 600], viewLower: [362, 360, 870, 600] };
export const PLOT_RECTS = { plots: [890, 100, 1270, 710] };
export const vividIn = (img, names) => names.reduce((sum, n) => sum + img.vivid[n], 0);

// A screenshot of the page, measured. With `until`, taken again until until(measures) holds
// (what a change of the state should draw: the app draws it on its next frame) or 20 s pass.
// The page's message line is hidden first, unless keepNotice (a test of what it says).
export async function screenshot(page, file, rects, until = null, keepNotice = false) {
  if (!keepNotice) await page.evaluate(() => { document.getElementById('notice').hidden = true; });
  const deadline = Date.now() + 20_000;
  let png, img;
  do {
    png = await page.screenshot({ path: join(outDir, file) });
    img = await analysePng(png, rects);
  } while (until && !until(img) && Date.now() < deadline);
  console.log(`      ${file} ${img.width}x${img.height}: ${img.distinct} colours, most common ${img.topColor} ` +
              `${(100 * img.topShare).toFixed(1)}%, vivid pixels ${JSON.stringify(img.vivid)} -> build/web-test/${file}`);
  return img;
}

// Clicks a button of the scenario panel where the app drew it, as a person's click (the app
// takes a press and release between two frames as a click).
export async function clickButton(page, label) {
  const r = await page.evaluate((l) => window.swarmlab.buttonRect(l), label);
  if (!r) return false;
  await page.mouse.click(r.x + r.width / 2, r.y + r.height / 2);
  return true;
}

// What the CLI says about a preset file ("error: FILE: field: problem" -> "field: problem").
export function cliMessage(json) {
  if (!existsSync(cliPath)) return null;
  const file = join(profile, 'bad-preset.json');
  writeFileSync(file, json);
  const r = spawnSync(cliPath, ['validate', file], { encoding: 'utf8', timeout: 20_000 });
  const m = /^error: .*?bad-preset\.json: (.*)$/m.exec(r.stderr || '');
  return m ? m[1].trim() : null;
}

/** Opens the browser at viewport (CSS pixels) with touch when asked; serviceWorkers: 'block'
 *  keeps the offline worker out (a route of the page's own then sees every fetch). */
export async function launchBrowser({ width = 1280, height = 720, hasTouch = false, isMobile = false,
                                      serviceWorkers = 'allow', locale = undefined } = {}) {
  mkdirSync(outDir, { recursive: true });
  profile = mkdtempSync(join(tmpdir(), 'swarmlab-chromium-'));
  context = await chromium.launchPersistentContext(profile, {
    executablePath: chromiumPath,
    headless: true,
    viewport: { width, height },
    hasTouch, isMobile, serviceWorkers,
    ...(locale ? { locale } : {}),  // the browser's language (navigator.languages), as a reader set it
    acceptDownloads: true,
    timeout: 30_000,
    args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
           '--disable-background-networking', '--disable-component-update', '--disable-sync',
           '--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
  });
  context.setDefaultTimeout(30_000);
  return context;
}

/** Runs main(url) against the served build/web, then prints the tally and exits non-zero on
 *  any failure. The watchdog measures progress, not the whole run: it fails the suite when no
 *  check has been made for stallMs (a loaded machine stretches every check alike, so a whole-run
 *  limit ran out under load while nothing was stuck). The suite's console log goes to
 *  build/web-test/NAME.log. `serve`: how build/web is served (Python's http.server;
 *  startWebServer for the real one). */
export async function runSuite(name, stallMs, main, { serve = startServer } = {}) {
  lastProgress = Date.now();
  let stalled = false;
  const watchdog = setInterval(async () => {
    if (stalled || Date.now() - lastProgress < stallMs) return;
    stalled = true;
    clearInterval(watchdog);
    // Where the app stood when time ran out (a page that still answers within 3 s), and a picture.
    const page = context?.pages().at(-1);
    const stood = page ? await Promise.race([page.evaluate(() => {
      const s = window.swarmlab.state();
      return `asleep ${window.swarmlab.sleeping()}, ${window.swarmlab.frames()} loop iterations, ` +
             `display ${s.display.width}x${s.display.height} (window ${innerWidth}x${innerHeight}), ` +
             `layout ${s.layout} settled ${s.layout_settled}, playing ${s.playing}, t = ${s.t}`;
    }).catch((e) => 'the page did not answer: ' + e.message.split('\n')[0]), sleep(3000).then(() => 'the page did not answer in 3 s')]) : 'no page';
    await page?.screenshot({ path: join(outDir, `${name}-timed-out.png`), timeout: 5000 }).catch(() => {});
    check(`${name}: a check is made at least every ${stallMs / 1000} s`, false, `stalled; ${stood}`);
    await Promise.race([cleanup(), sleep(3000)]);
    finish();
  }, 1000);
  try {
    mkdirSync(outDir, { recursive: true });
    await main(await serve());
  } catch (e) {
    check(`${name} run`, false, String(e && e.stack || e).split('\n').slice(0, 3).join(' / '));
  }
  writeFileSync(join(outDir, `${name}.log`), consoleLog.join('\n') + '\n');
  clearInterval(watchdog);
  await cleanup();
  finish();
}
