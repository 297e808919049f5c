// End-to-end check of the browser build in build/web, in Debian's headless Chromium (WebGL2 on
// SwiftShader) driven by playwright-core. Run through tests/web/run.sh (builds nothing itself).
// Serves build/web with python3's http.server on 127.0.0.1 at a free port, loads the page, waits
// for frames, screenshots to build/web-test/screenshot.png and checks what a person would see.
// The last line is "N passed, M failed"; the exit code is non-zero on any failure.
import { chromium } from 'playwright-core';
import { spawn } from 'node:child_process';
import { mkdtempSync, mkdirSync, rmSync, statSync, existsSync, writeFileSync } from 'node:fs';
import { createServer } from 'node:net';
import { tmpdir } from 'node:os';
import { join, dirname, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = resolve(dirname(fileURLToPath(import.meta.url)), '../..');
const webDir = process.env.SWARMLAB_WEB_DIR || join(root, 'build/web');
const outDir = join(root, 'build/web-test');
const chromiumPath = process.env.CHROMIUM || '/usr/bin/chromium';
const WASM_LIMIT = 4 * 1024 * 1024;
const OVERALL_MS = 110_000; // the whole run, browser included, stays under 2 minutes

let passed = 0, failed = 0;
function check(name, ok, detail = '') {
  if (ok) { passed++; console.log(`ok    ${name}${detail ? ' (' + detail + ')' : ''}`); }
  else { failed++; console.log(`FAIL  ${name}${detail ? ': ' + detail : ''}`); }
  return ok;
}
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

let server = null, context = null, profile = null;
async function cleanup() {
  if (context) await context.close().catch(() => {});
  context = null;
  if (server && server.exitCode === null) server.kill('SIGTERM');
  if (profile) rmSync(profile, { recursive: true, force: true });
}
function finish() {
  console.log(`${passed} passed, ${failed} failed`);
  process.exit(failed > 0 || passed === 0 ? 1 : 0);
}
const watchdog = setTimeout(async () => {
  check('whole run within ' + OVERALL_MS / 1000 + ' s', false, 'timed out');
  await Promise.race([cleanup(), sleep(3000)]);
  finish();
}, OVERALL_MS);

function freePort() {
  return new Promise((res, rej) => {
    const s = createServer();
    s.once('error', rej);
    s.listen(0, '127.0.0.1', () => { const { port } = s.address(); s.close(() => res(port)); });
  });
}

async function startServer() {
  const port = await freePort();
  server = spawn('python3', ['-m', 'http.server', '--bind', '127.0.0.1', '--directory', webDir, String(port)],
                 { stdio: ['ignore', 'ignore', 'ignore'] });
  const url = `http://127.0.0.1:${port}/`;
  const deadline = Date.now() + 10_000;
  while (Date.now() < deadline) {
    if (server.exitCode !== null) throw new Error('http.server exited with ' + server.exitCode);
    try { if ((await fetch(url)).ok) return url; } catch { /* not up yet */ }
    await sleep(100);
  }
  throw new Error('http.server did not answer on ' + url);
}

// Decodes a PNG in a blank page and measures it: distinct colours (quantised to 4 bits per
// channel), the share of the most common colour, and the share of pure black pixels.
async function analysePng(page, png) {
  return page.evaluate(async (b64) => {
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
    return { width: c.width, height: c.height, distinct: counts.size, topShare: top / n,
             topColor: '#' + topKey.toString(16).padStart(3, '0'), blackShare: black / n };
  }, png.toString('base64'));
}

async function main() {
  // 1. The build output.
  for (const f of ['index.html', 'swarmlab.js', 'swarmlab.wasm']) {
    if (!check(`build/web/${f} exists`, existsSync(join(webDir, f)))) return;
  }
  const wasmSize = statSync(join(webDir, 'swarmlab.wasm')).size;
  check('swarmlab.wasm < 4 MB', wasmSize < WASM_LIMIT, `${(wasmSize / 1048576).toFixed(2)} MB`);

  const url = await startServer();
  mkdirSync(outDir, { recursive: true });
  profile = mkdtempSync(join(tmpdir(), 'swarmlab-chromium-'));
  context = await chromium.launchPersistentContext(profile, {
    executablePath: chromiumPath,
    headless: true,
    viewport: { width: 1280, height: 720 },
    timeout: 30_000,
    args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
           '--disable-background-networking', '--disable-component-update', '--disable-sync',
           '--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
  });
  context.setDefaultTimeout(30_000);

  // 2. The app starts and renders frames.
  const page = context.pages()[0] || await context.newPage();
  const pageErrors = [], consoleErrors = [], consoleLog = [];
  page.on('pageerror', (e) => pageErrors.push(String(e)));
  page.on('response', (r) => { if (r.status() >= 400) consoleErrors.push(`HTTP ${r.status()} for ${r.url()}`); });
  page.on('console', (m) => {
    consoleLog.push(`[${m.type()}] ${m.text()}`);
    if (m.type() === 'error' && !/^Failed to load resource/.test(m.text())) consoleErrors.push(m.text());
  });
  const tNav = Date.now();
  await page.goto(url, { waitUntil: 'load' });
  let started = true;
  try {
    await page.waitForFunction(() => window.swarmlabError || (window.swarmlab && window.swarmlab.frames() >= 10),
                               null, { timeout: 45_000, polling: 100 });
  } catch (e) { started = false; }
  const wallToTen = Date.now() - tNav;
  const state = await page.evaluate(() => ({
    error: window.swarmlabError || null,
    hasApi: !!window.swarmlab,
    frames: window.swarmlab ? window.swarmlab.frames() : 0,
    firstFrameMs: window.swarmlab ? window.swarmlab.firstFrameMs : null,
    status: document.getElementById('status').textContent,
    overlayHidden: document.getElementById('overlay').classList.contains('hidden'),
    canvas: [document.getElementById('canvas').width, document.getElementById('canvas').height],
    nav: (() => { const n = performance.getEntriesByType('navigation')[0]; return n ? { dcl: n.domContentLoadedEventEnd, load: n.loadEventEnd } : null; })(),
  }));
  if (!check('the app starts and renders frames', started && !state.error && state.frames >= 10,
             started ? (state.error || `${state.frames} frames`) : `timeout; status "${state.status}"`)) {
    for (const line of consoleLog.slice(-20)) console.log('      ' + line);
  }
  check('window.swarmlab API present', state.hasApi);
  check('loading overlay hidden after the first frame', state.overlayHidden);
  check('canvas fills the window', state.canvas[0] >= 1280 && state.canvas[1] >= 720, state.canvas.join('x'));
  if (state.firstFrameMs !== null) {
    console.log(`      page load to first frame: ${Math.round(state.firstFrameMs)} ms after navigation start ` +
                `(DOMContentLoaded ${Math.round(state.nav?.dcl ?? -1)} ms, load ${Math.round(state.nav?.load ?? -1)} ms; ` +
                `10 frames after ${wallToTen} ms wall clock)`);
  }
  check('first frame within 20 s of navigation', state.firstFrameMs !== null && state.firstFrameMs < 20_000,
        state.firstFrameMs !== null ? `${Math.round(state.firstFrameMs)} ms` : 'no frame');

  // 3. The JS API: the simulated clock advances, presets round-trip, bad JSON is refused.
  if (state.hasApi && started && !state.error) {
    const t1 = await page.evaluate(() => window.swarmlab.time());
    await sleep(700);
    const t2 = await page.evaluate(() => window.swarmlab.time());
    check('swarmlab.time() advances', typeof t1 === 'number' && t2 > t1, `${t1.toFixed(3)} -> ${t2.toFixed(3)}`);
    const api = await page.evaluate(() => {
      const out = {};
      try { out.preset = window.swarmlab.preset(); } catch (e) { out.presetError = String(e); }
      try { out.reload = window.swarmlab.load(out.preset); } catch (e) { out.reloadError = String(e); }
      try { window.swarmlab.load('{ this is not json'); out.badAccepted = true; } catch (e) { out.badError = String(e); }
      return out;
    });
    check('swarmlab.preset() returns an object', api.preset && typeof api.preset === 'object', api.presetError || JSON.stringify(api.preset).slice(0, 80));
    check('swarmlab.load(preset()) accepts the current preset', api.reload === true, api.reloadError || '');
    check('swarmlab.load() rejects malformed JSON', !api.badAccepted && !!api.badError, api.badError || 'accepted');
    await sleep(300); // a few frames after the reload
  }

  // 4. What a person sees: a screenshot that is not blank.
  const png = await page.screenshot({ path: join(outDir, 'screenshot.png') });
  const scratch = await context.newPage();
  await scratch.setContent('<html><body></body></html>');
  const img = await analysePng(scratch, png);
  await scratch.close();
  console.log(`      screenshot ${img.width}x${img.height}: ${img.distinct} colours, most common ${img.topColor} ` +
              `${(100 * img.topShare).toFixed(1)}%, black ${(100 * img.blackShare).toFixed(1)}% -> build/web-test/screenshot.png`);
  check('screenshot is not blank', img.distinct >= 16 && img.topShare < 0.98, `${img.distinct} colours`);
  check('canvas is not black (WebGL drew)', img.blackShare < 0.5, `${(100 * img.blackShare).toFixed(1)}% black`);

  check('no uncaught page errors', pageErrors.length === 0, pageErrors.slice(0, 3).join(' | '));
  check('no console errors', consoleErrors.length === 0, consoleErrors.slice(0, 3).join(' | '));
  writeFileSync(join(outDir, 'console.log'), consoleLog.join('\n') + '\n');

  // 5. Without WebGL2 the page says so instead of loading the app.
  const noGl = await context.newPage();
  await noGl.addInitScript(() => {
    const orig = HTMLCanvasElement.prototype.getContext;
    HTMLCanvasElement.prototype.getContext = function (type, ...rest) {
      return type === 'webgl2' ? null : orig.call(this, type, ...rest);
    };
  });
  await noGl.goto(url, { waitUntil: 'load' });
  await sleep(300);
  const msg = await noGl.evaluate(() => ({
    error: window.swarmlabError || '', loaded: !!window.Module || !!document.querySelector('script[src^="swarmlab.js"]'),
    visible: !document.getElementById('overlay').classList.contains('hidden'),
  }));
  check('without WebGL2: a clear message and no download', /WebGL 2/.test(msg.error) && !msg.loaded && msg.visible,
        msg.error.slice(0, 60));
  await noGl.screenshot({ path: join(outDir, 'no-webgl2.png') });
  await noGl.close();
}

try {
  await main();
} catch (e) {
  check('test run', false, String(e && e.stack || e).split('\n').slice(0, 3).join(' / '));
}
clearTimeout(watchdog);
await cleanup();
finish();
