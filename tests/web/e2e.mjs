// End-to-end check of the browser app in build/web, in Debian's headless Chromium (WebGL2 on
// SwiftShader) driven by playwright-core. Run through tests/web/run.sh (builds nothing itself).
// Serves build/web with python3's http.server on 127.0.0.1 at a free port and checks what a
// person would see and what a page embedding the app relies on:
//   the page starts within 3 s; particles and plots are drawn (pixel checks on screenshots in
//   build/web-test/); the simulated clock advances (window.swarmlab.time()); the shipped presets
//   are in the list; share links (#preset= and the compressed #z=) start their preset; a link
//   or a load() whose preset fails validation shows the CLI's message and the app keeps running;
//   Download preset and Open preset move JSON files; Space pauses; hostile input (a preset of
//   1.32 million characters, one over the 4 MB limit, a 6-million-character #preset=, a
//   1.5-million-character link, a deflate bomb) never stalls the tab for a second or stops the drawing; no
//   WebGL2 gives a clear message.
// The last line is "N passed, M failed"; the exit code is non-zero on any failure.
import { statSync, existsSync, writeFileSync, readFileSync, readdirSync } from 'node:fs';
import { join } from 'node:path';
import { deflateRawSync, constants as zlibConstants } from 'node:zlib';
import * as harness from './harness.mjs';

const { root, webDir, outDir, check, base64url, shipped, openApp, state, clockAdvances, clockStands,
        keepsDrawing, screenshot, clickButton, cliMessage, launchBrowser, runSuite, pageErrors,
        consoleErrors, consoleLog, WASM_LIMIT, START_LIMIT_MS, DEFAULT_PRESET, VIEW_RECTS, PLOT_RECTS, vividIn,
        cliPath, published } = harness;

async function main(url) {
  // 1. The build output.
  if (!check('build/web/index.html exists', existsSync(join(webDir, 'index.html')))) return;
  for (const f of ['swarmlab.js', 'swarmlab.wasm']) {
    const name = published(f);
    if (!check(`build/web has ${f}, under a name with its content's hash`,
               /\.[0-9a-f]{8}\./.test(name) && existsSync(join(webDir, name)), String(name))) return;
  }
  const wasmSize = statSync(join(webDir, published('swarmlab.wasm'))).size;
  check('swarmlab.wasm < 4 MB', wasmSize < WASM_LIMIT, `${(wasmSize / 1048576).toFixed(2)} MB`);

  const context = await launchBrowser({ width: 1280, height: 720 });
  const blank = context.pages()[0];

  // 2. The app starts within 3 s and renders frames.
  const { page, started, error } = await openApp(url, 'main');
  if (blank) await blank.close();
  const boot = await page.evaluate(() => ({
    hasApi: !!window.swarmlab,
    frames: window.swarmlab ? window.swarmlab.frames() : 0,
    firstFrameMs: window.swarmlab ? window.swarmlab.firstFrameMs : null,
    status: document.getElementById('status').textContent,
    overlayHidden: document.getElementById('overlay').classList.contains('hidden'),
    canvas: [document.getElementById('canvas').width, document.getElementById('canvas').height],
    nav: (() => { const n = performance.getEntriesByType('navigation')[0]; return n ? { dcl: n.domContentLoadedEventEnd, load: n.loadEventEnd } : null; })(),
  }));
  if (!check('the app starts and renders frames', started, started ? `${boot.frames} frames` : (error || `timeout; status "${boot.status}"`))) {
    for (const line of consoleLog.slice(-20)) console.log('      ' + line);
    return;
  }
  check('window.swarmlab API present', boot.hasApi);
  check('loading overlay hidden after the first frame', boot.overlayHidden);
  check('canvas fills the window', boot.canvas[0] >= 1280 && boot.canvas[1] >= 720, boot.canvas.join('x'));
  console.log(`      page load to first frame: ${Math.round(boot.firstFrameMs)} ms after navigation start ` +
              `(DOMContentLoaded ${Math.round(boot.nav?.dcl ?? -1)} ms, load ${Math.round(boot.nav?.load ?? -1)} ms)`);
  check(`page loads and starts within ${START_LIMIT_MS / 1000} s`, boot.firstFrameMs !== null && boot.firstFrameMs < START_LIMIT_MS,
        boot.firstFrameMs !== null ? `first frame at ${Math.round(boot.firstFrameMs)} ms` : 'no frame');

  // 3. The JS API and the shipped presets.
  const clock = await clockAdvances(page);
  check('swarmlab.time(): the simulated clock advances', clock.ok, clock.detail);
  const first = await page.evaluate(() => window.swarmlab.preset());
  let firstPreset = null;
  try { firstPreset = JSON.parse(first); } catch { /* checked below */ }
  check('swarmlab.preset() is a JSON string of the running preset', typeof first === 'string' && firstPreset?.name === DEFAULT_PRESET,
        firstPreset ? `"${firstPreset.name}"` : String(first).slice(0, 60));
  const files = readdirSync(join(root, 'assets/presets')).filter((f) => f.endsWith('.json')).sort();
  const list = await page.evaluate(() => window.swarmlab.shipped());
  check('every shipped preset is in the browser\'s preset list', files.every((f) => list.some((p) => p.id === f)),
        `${list.length} of ${files.length}`);
  const reload = await page.evaluate((text) => { try { return window.swarmlab.load(text); } catch (e) { return String(e); } }, first);
  check('swarmlab.load(swarmlab.preset()) accepts the running preset', reload === true, String(reload));

  // 4. What a person sees: particles in the 3D view, lines in the plots.
  await page.waitForFunction(() => window.swarmlab.time() >= 2, null, { timeout: 30_000 }).catch(() => {}); // the plots fill up
  const shot = await screenshot(page, 'screenshot.png', { ...VIEW_RECTS, ...PLOT_RECTS });
  check('screenshot is not blank', shot.distinct >= 16 && shot.topShare < 0.98, `${shot.distinct} colours`);
  check('canvas is not black (WebGL drew)', shot.blackShare < 0.5, `${(100 * shot.blackShare).toFixed(1)}% black`);
  check('particles are drawn in the 3D view', vividIn(shot, ['viewRight', 'viewLower']) >= 150,
        `${vividIn(shot, ['viewRight', 'viewLower'])} coloured pixels`);
  check('plots are drawn', shot.vivid.plots >= 300, `${shot.vivid.plots} coloured pixels in the plot panel`);

  // 5. Keyboard input reaches the app: Space pauses and resumes (a person's press: the app
  // takes a press between two frames as one).
  const playing = (p) => page.waitForFunction((want) => window.swarmlab.state().playing === want, p, { timeout: 10_000 }).catch(() => {});
  await page.mouse.click(620, 300); // focus the canvas (a click in the 3D view selects or deselects)
  await page.keyboard.press('Space');
  await playing(false);
  const paused = await clockStands(page);
  await page.keyboard.press('Space');
  await playing(true);
  const resumed = await clockAdvances(page);
  check('Space pauses and resumes the run', paused.ok && resumed.ok, `paused ${paused.detail}, resumed ${resumed.detail}`);

  // 6. load() of a preset that fails validation: the CLI's message, thrown and shown; the run goes on.
  const bad = { ...shipped('two-body-circular.json'), dt: -1 };
  const badJson = JSON.stringify(bad, null, 2);
  const cli = cliMessage(badJson);
  if (cli === null) console.log(`      (no native CLI at ${cliPath}: the messages are not compared with it)`);
  const expected = cli ?? 'dt:';
  const rejected = await page.evaluate((text) => { try { window.swarmlab.load(text); return null; } catch (e) { return e.message; } }, badJson);
  let after = await state(page);
  check('load() of a bad preset throws the CLI\'s message', !!rejected && rejected.includes(expected), rejected || 'accepted');
  check('load() of a bad preset: the message is shown on the page', after.noticeKind === 'error' && after.notice.includes(expected),
        after.notice.slice(0, 100));
  let going = await clockAdvances(page);
  check('load() of a bad preset: the previous preset keeps running', after.preset?.name === DEFAULT_PRESET && going.ok,
        `"${after.preset?.name}", ${going.detail}`);
  const malformed = await page.evaluate(() => { try { window.swarmlab.load('{ this is not json'); return null; } catch (e) { return e.message; } });
  check('load() rejects malformed JSON', !!malformed, malformed || 'accepted');

  // 6b. Hostile but well-formed presets: ten million particles (beyond a Chromebook's ~1 GB) and
  //     an isolated repulsive pair run past the point where its energies overflow. Refused
  //     within a second or two with the field named; the previous preset keeps running.
  const hostile = [
    ['ten million particles', { name: 'E2E huge', J: 1, particles: { count: 10000000, position_radius: 1, velocity: { speed: 1 } }, dt: 1e-3, duration: 1 },
     'particles.count: 1e+07 particles need'],
    ['a pair that overflows to NaN', { name: 'E2E NaN', J: -1, particles: [{ m: 1, r: [0.5, 0, 0], v: [0, 0, 0] }, { m: 1, r: [-0.5, 0, 0], v: [0, 0, 0] }], dt: 0.01, duration: 494.97474683058323 },
     "duration: an isolated repulsive system's energies grow as exp(2 Omega t)"],
  ];
  for (const [what, preset, message] of hostile) {
    const started = Date.now();
    const refused = await page.evaluate((text) => { try { window.swarmlab.load(text); return null; } catch (e) { return e.message; } }, JSON.stringify(preset));
    const ms = Date.now() - started;
    after = await state(page);
    going = await clockAdvances(page);
    check(`load() of ${what}: refused within 2 s naming the field`, !!refused && refused.includes(message) && ms < 2000,
          `${ms} ms: ${refused || 'accepted'}`);
    check(`load() of ${what}: the previous preset keeps running`, after.preset?.name === DEFAULT_PRESET && going.ok,
          `"${after.preset?.name}", ${going.detail}`);
  }

  // 7. Download preset (the scenario panel's button, clicked) and Open preset (a file picker).
  const [download, clicked] = await Promise.all([page.waitForEvent('download', { timeout: 10_000 }).catch(() => null),
                                                 clickButton(page, 'Download preset')]);
  const downloaded = download ? readFileSync(await download.path(), 'utf8') : '';
  check('Download preset button: the running preset as a JSON file', clicked && download &&
        download.suggestedFilename().endsWith('.json') && JSON.parse(downloaded).name === DEFAULT_PRESET,
        download ? `${download.suggestedFilename()}, ${downloaded.length} bytes` : clicked ? 'no download' : 'button not found');
  const upload = { ...shipped('fig4-equilibration.json'), name: 'E2E uploaded preset' };
  const [chooser] = await Promise.all([page.waitForEvent('filechooser', { timeout: 10_000 }),
                                       page.evaluate(() => window.swarmlab.openFile())]);
  await chooser.setFiles({ name: 'e2e-upload.json', mimeType: 'application/json', buffer: Buffer.from(JSON.stringify(upload)) });
  await page.waitForFunction(() => JSON.parse(window.swarmlab.preset()).name === 'E2E uploaded preset', null, { timeout: 5000 }).catch(() => {});
  after = await state(page);
  check('Open preset: an uploaded file starts running', after.preset?.name === 'E2E uploaded preset', `"${after.preset?.name}"`);

  // 8. Share links: #preset= (base64url JSON) and #z= (deflate-raw), each in a new page.
  const linked = { ...shipped('fig3-repulsive-fireball.json'), name: 'E2E plain link \u03c9 \u2192 \u221e' };
  const plainUrl = url + '#preset=' + base64url(JSON.stringify(linked));
  const plain = await openApp(plainUrl, 'link');
  if (check('a #preset= link starts', plain.started, plain.error || '')) {
    const s = await state(plain.page);
    going = await clockAdvances(plain.page);
    check('a #preset= link runs its preset (swarmlab.preset())', s.preset?.name === linked.name &&
          s.preset?.J === linked.J && going.ok && !s.notice, `"${s.preset?.name}", ${going.detail}`);
    await plain.page.close();
  }
  const zipped = { ...shipped('fig2-attractive-expansion.json'), name: 'E2E compressed link' };
  const zJson = JSON.stringify(zipped);
  const zUrl = url + '#z=' + base64url(deflateRawSync(Buffer.from(zJson)));
  const z = await openApp(zUrl, 'z-link');
  if (check('a #z= (deflate-raw) link starts', z.started, z.error || '')) {
    const s = await state(z.page);
    check('a #z= link runs its preset (swarmlab.preset())', s.preset?.name === zipped.name && !s.notice,
          `"${s.preset?.name}", link ${zUrl.length - url.length} characters`);
    const img = await screenshot(z.page, 'screenshot-swarm.png', { ...VIEW_RECTS, ...PLOT_RECTS });
    check('a swarm\'s particles are drawn', vividIn(img, ['viewRight', 'viewLower']) >= 300,
          `${vividIn(img, ['viewRight', 'viewLower'])} coloured pixels`);
    // Copy link (the button, clicked): the running preset into the address, the same preset back from it.
    await z.page.evaluate(() => history.replaceState(null, '', location.pathname));
    const clickedCopy = await clickButton(z.page, 'Copy link');
    // A person waits for the notice that shows the link (the address changes first, the notice
    // and swarmlab.link() with the frame after: the first sign of change is not the end of it).
    await z.page.waitForFunction(() => {
      const notice = document.getElementById('notice');
      return !notice.hidden && notice.className === 'link' && document.getElementById('notice-link').value !== '';
    }, null, { timeout: 30_000 }).catch(() => {});
    const shown = await state(z.page);
    const copied = await z.page.evaluate(() => location.href);
    const linkShown = await z.page.evaluate(() => document.getElementById('notice-link').value);
    const apiLink = await z.page.evaluate(() => window.swarmlab.link());
    check('Copy link button puts the preset in the address and shows the link', clickedCopy && /^#lang=en&(z|preset)=/.test(shown.hash) &&
          shown.noticeKind === 'link' && linkShown === copied && apiLink === copied,
          `${shown.hash.slice(0, 24)}... (${shown.hash.length} characters)`);
    const running = await z.page.evaluate(() => window.swarmlab.preset());
    await z.page.close();
    const again = await openApp(copied, 'copied-link');
    if (check('the copied link starts', again.started, again.error || '')) {
      const back = await again.page.evaluate(() => window.swarmlab.preset());
      check('the copied link runs the same preset', back === running, back === running ? '' : back.slice(0, 80));
      await again.page.close();
    }
  }

  // 9. A link whose preset fails validation, and one that does not decode: the message, and the
  //    default preset keeps running.
  const badLinks = [['#preset= link with an invalid preset', '#preset=' + base64url(badJson), expected],
                    ['#z= link that does not decompress', '#z=' + base64url(Buffer.from('not deflate at all')), 'share link:']];
  for (const [what, hash, message] of badLinks) {
    const b = await openApp(url + hash, 'bad-link');
    if (!check(`${what}: the app starts anyway`, b.started, b.error || '')) continue;
    const s = await state(b.page);
    going = await clockAdvances(b.page);
    check(`${what}: a clear message on the page`, s.noticeKind === 'error' && s.notice.includes('share link') && s.notice.includes(message),
          s.notice.slice(0, 110));
    check(`${what}: the default preset keeps running`, s.preset?.name === DEFAULT_PRESET && going.ok, `"${s.preset?.name}", ${going.detail}`);
    if (hash.startsWith('#preset=')) await b.page.screenshot({ path: join(outDir, 'bad-link.png') });
    await b.page.close();
  }

  // 10. Hostile input: a long preset, one over the 4 MB limit, long links and a deflate bomb.
  //     Each is refused within a second (the message names the size and the limit) or loaded
  //     (a 1.2-million-character link within two), and the app keeps drawing.
  // The longest stall of the page's main thread while `action` runs in the page, from a 20 ms
  // interval timer (ms), the action's result and how long it took.
  const timed = (p, action, arg) => p.evaluate(async ([source, arg]) => {
    let last = performance.now(), stall = 0;
    const timer = setInterval(() => { const now = performance.now(); stall = Math.max(stall, now - last); last = now; }, 20);
    const t0 = performance.now();
    let result;
    try { result = await (0, eval)(source)(arg); } catch (e) { result = 'threw: ' + e.message; }
    const ms = performance.now() - t0;
    await new Promise((r) => setTimeout(r, 60));
    clearInterval(timer);
    return { result, ms, stall: Math.max(stall, performance.now() - last) };
  }, [action.toString(), arg]);
  // The app keeps drawing (four frames, however slowly a loaded machine draws them) and answers.
  const drawing = async (p) => {
    const drawn = await keepsDrawing(p, 4);
    const works = await p.evaluate(() => { try { return typeof JSON.parse(window.swarmlab.preset()).J === 'number'; } catch { return false; } });
    return { ok: drawn.ok && works, detail: `${drawn.detail}, preset() ${works ? 'works' : 'fails'}` };
  };
  const errorsBefore = pageErrors.length;
  const long = await timed(page, (n) => {
    const p = { J: 1, particles: { count: 10, position_radius: 1, velocity: { speed: 1 } }, dt: 0.01, duration: 1, description: 'x'.repeat(n) };
    try { window.swarmlab.load(JSON.stringify(p)); return 'loaded'; } catch (e) { return 'refused: ' + e.message; }
  }, 1_320_000);
  let draws = await drawing(page);
  check('load() of 1.32 million characters: the app keeps drawing and preset() works', draws.ok && pageErrors.length === errorsBefore,
        `${long.result.slice(0, 60)}; ${draws.detail}; ${pageErrors.slice(errorsBefore).join(' | ')}`);
  await page.evaluate((json) => window.swarmlab.load(json), JSON.stringify(upload));
  const huge = await timed(page, (n) => {
    try { window.swarmlab.load(JSON.stringify({ J: 1, description: 'y'.repeat(n) })); return 'loaded'; } catch (e) { return e.message; }
  }, 5_000_000);
  after = await state(page);
  draws = await drawing(page);
  check('load() of 5 MB: refused with the size and the limit, shown on the page', /5 MB; a preset may be at most 4 MB/.test(huge.result) &&
        after.noticeKind === 'error' && after.notice.includes('at most 4 MB'), huge.result.slice(0, 100));
  check('load() of 5 MB: the previous preset keeps running', after.preset?.name === upload.name && draws.ok, `"${after.preset?.name}", ${draws.detail}`);
  const longPlain = await timed(page, (n) => window.swarmlab.openLink('#preset=' + 'A'.repeat(n)), 6_000_000);
  after = await state(page);
  check('openLink() of a 6-million-character #preset=: refused before decoding, within a second',
        /at most 4 MB/.test(longPlain.result) && longPlain.ms < 1000 && longPlain.stall < 1000 && after.preset?.name === upload.name,
        `${longPlain.result.slice(0, 90)}; ${longPlain.ms.toFixed(0)} ms, longest stall ${longPlain.stall.toFixed(0)} ms`);
  // A deflate bomb: 1 GiB of zeros in about 1 MB. One MiB of zeros deflated with a full flush is
  // a byte-aligned run of blocks that can be repeated; an empty final block ends the stream.
  const mib = deflateRawSync(Buffer.alloc(1 << 20), { finishFlush: zlibConstants.Z_FULL_FLUSH });
  const bomb = Buffer.concat([...Array(1024).fill(mib), deflateRawSync(Buffer.alloc(0))]);
  const bombHash = '#z=' + base64url(bomb);
  const burst = await timed(page, (hash) => window.swarmlab.openLink(hash), bombHash);
  after = await state(page);
  draws = await drawing(page);
  check('a deflate bomb #z= (1 GiB in 1 MB): stopped at the limit within a second', /inflates to more than 4 MB/.test(burst.result) &&
        burst.ms < 1000 && burst.stall < 1000, `${burst.result.slice(0, 90)}; ${burst.ms.toFixed(0)} ms, longest stall ${burst.stall.toFixed(0)} ms`);
  check('a deflate bomb #z=: the previous preset keeps running, the message on the page', after.preset?.name === upload.name &&
        draws.ok && after.notice.includes('inflates to more than'), `"${after.preset?.name}", ${draws.detail}`);
  // As the address a page opens with: a smaller bomb (64 MiB) keeps the address short.
  const smallBomb = Buffer.concat([...Array(64).fill(mib), deflateRawSync(Buffer.alloc(0))]);
  const bombed = await openApp(url + '#z=' + base64url(smallBomb), 'bomb-link');
  if (check('a deflate bomb as the start link (64 MiB): the app starts anyway', bombed.started, bombed.error || '')) {
    const s = await state(bombed.page);
    const first = await bombed.page.evaluate(() => window.swarmlab.firstFrameMs);
    check('a deflate bomb as the start link: the message, and the default preset runs', s.noticeKind === 'error' &&
          s.notice.includes('inflates to more than 4 MB') && s.preset?.name === DEFAULT_PRESET && (await drawing(bombed.page)).ok,
          `first frame at ${first?.toFixed(0)} ms; ${s.notice.slice(0, 80)}`);
    await bombed.page.close();
  }
  // A long #preset= link (1.5 million characters), through openLink(), what a link pasted into
  // the address runs. (Chromium itself takes seconds to change the address to such a URL;
  // that part is the browser's.)
  // Long because it lists 12,000 particles (a string over 64 kB would be refused by its rule).
  // Every particle is read and checked in the page's one thread: 0.35-0.47 s of stall on a quiet
  // 2-core machine, 1.4 s on a slower CI machine before the reader stopped building a message
  // per particle. Refusals above stop within a second; reading a link this long may take two,
  // never a frozen tab.
  const longParticles = Array.from({ length: 12000 }, (_, i) => {
    const x = (k) => Number((0.5 * Math.sin(i * 12.9898 + k * 78.233)).toFixed(6));
    return { m: 1, r: [x(1), x(2), x(3)], v: [x(4), x(5), x(6)] };
  });
  const longLinked = { name: 'E2E long link', J: 1e-4, particles: longParticles, container: { radius: 1 }, dt: 0.01, duration: 10 };
  const longHash = '#preset=' + base64url(JSON.stringify(longLinked));
  const opened = await timed(page, (hash) => window.swarmlab.openLink(hash), longHash);
  after = await state(page);
  draws = await drawing(page);
  check(`a ${(longHash.length / 1e6).toFixed(1)}-million-character #preset= link: its preset runs, the app keeps drawing`,
        opened.result === '' && after.preset?.name === longLinked.name && after.preset?.particles?.length === longParticles.length &&
        opened.stall < 2000 && draws.ok,
        `${opened.result ? opened.result.slice(0, 80) + '; ' : ''}"${after.preset?.name}" after ${opened.ms.toFixed(0)} ms, longest stall ${opened.stall.toFixed(0)} ms; ${draws.detail}`);

  check('no uncaught page errors', pageErrors.length === 0, pageErrors.slice(0, 3).join(' | '));
  check('no console errors', consoleErrors.length === 0, consoleErrors.slice(0, 3).join(' | '));

  // 11. Without WebGL2 the page says so instead of loading the app.
  const noGl = await context.newPage();
  await noGl.addInitScript(() => {
    const orig = HTMLCanvasElement.prototype.getContext;
    HTMLCanvasElement.prototype.getContext = function (type, ...rest) {
      return type === 'webgl2' ? null : orig.call(this, type, ...rest);
    };
  });
  await noGl.goto(url, { waitUntil: 'load' });
  await noGl.waitForFunction(() => window.swarmlabError, null, { timeout: 10_000 }).catch(() => {});
  const msg = await noGl.evaluate(() => ({
    error: window.swarmlabError || '', loaded: !!window.Module || !!document.querySelector('script[src^="swarmlab."]'),
    visible: !document.getElementById('overlay').classList.contains('hidden'),
  }));
  check('without WebGL2: a clear message and no download', /WebGL 2/.test(msg.error) && !msg.loaded && msg.visible,
        msg.error.slice(0, 60));
  await noGl.screenshot({ path: join(outDir, 'no-webgl2.png') });
  await noGl.close();
}

await runSuite('e2e', 110_000, main);
