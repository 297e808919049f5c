// Embedding in a course page (web/embed_bridge.js, web/examples/course.html). The app is served
// on one port (harness.mjs), the example course page from a second (a small node server here:
// another origin), and it embeds the app from the first with its own origin on the allow-list
// (?embed&origins=...). Checked:
//   a link to the course page with a hostile ?app= (javascript: in several spellings, data:,
//   blob:, file:, vbscript:, a user and password, a tab or a newline, an address that does not parse) runs
//   nothing (no dialog to the suite's end, no mark on the page), sets no frame address and
//   says on the page what it refused; its Content-Security-Policy refuses an injected inline
//   script, a javascript: frame and a data: frame;
//   the app in the frame says it is ready to the course page; it shows no menu bar (no menu
//   item in its parallel DOM, state().menus empty) and no welcome, and gets them back with
//   set({embed: false}) through the bridge (so the check can see a menu bar);
//   the course page's buttons load a preset, read P and T via state and open a lesson, and the
//   app shows each (its own state, read by the test);
//   bad messages get an error reply naming what is wrong: an unknown call, wrong arguments,
//   a bad key or preset, another version, a bad id, a 6-million-character payload, a cycle,
//   indices that a 32-bit int would wrap (select(2^32 + 2), screenPosition(2^32 + 1)) or that
//   are no safe integer (select(2^53)), which select nothing;
//   the app keeps drawing;
//   a page on a third port embedding the same address (only the course page's origin listed)
//   gets no reply to its calls nor the ready message, and its calls change nothing.
// Every wait is on a condition (a reply arriving, a state). Screenshots of the course page at
// a laptop's and a phone's size go to build/web-test/embed-course-*.png.
import { createServer } from 'node:http';
import { readFileSync, existsSync } from 'node:fs';
import { join } from 'node:path';
import * as harness from './harness.mjs';

const { webDir, outDir, check, launchBrowser, runSuite, pageErrors, consoleErrors, watch,
        freePort, analysePng } = harness;

const DEFAULT = harness.DEFAULT_PRESET;
const HOT_WALL = 'A hot wall warms a cold gas';

// A node http server on 127.0.0.1 answering each path from pages (path -> HTML text).
async function serve(pages) {
  const port = await freePort();
  const server = createServer((req, res) => {
    const path = new URL(req.url, 'http://x').pathname;
    const body = pages[path];
    res.writeHead(body === undefined ? 404 : 200, { 'Content-Type': 'text/html; charset=utf-8' });
    res.end(body === undefined ? 'not found' : body);
  });
  await new Promise((resolve) => server.listen(port, '127.0.0.1', resolve));
  // The browser keeps its connections alive: end them, or close() waits for them.
  return { origin: `http://127.0.0.1:${port}`, close: () => new Promise((r) => { server.close(r); server.closeAllConnections(); }) };
}

// The app's frame in a page, once it has drawn its first frame (or null after timeoutMs).
async function appFrame(page, appUrl, timeoutMs = 40_000) {
  const deadline = Date.now() + timeoutMs;
  while (Date.now() < deadline) {
    const frame = page.frames().find((f) => f.url().startsWith(appUrl));
    if (frame) {
      const ok = await frame.waitForFunction(() => window.swarmlabError || (window.swarmlab && window.swarmlab.firstFrameMs !== null),
                                             null, { timeout: Math.max(1000, deadline - Date.now()) })
        .then(() => true, () => false);
      if (ok && !(await frame.evaluate(() => window.swarmlabError || null))) return frame;
      return null;
    }
    await page.waitForEvent('frameattached', { timeout: Math.max(1000, deadline - Date.now()) }).catch(() => {});
  }
  return null;
}

// Posts a message from the course page to its frame; resolves to the reply with the same id
// (or null after timeoutMs). Runs in the page.
function postAndWait(message, timeoutMs) {
  const frame = document.getElementById('swarmlab');
  return new Promise((resolve) => {
    const timer = setTimeout(() => { removeEventListener('message', on); resolve(null); }, timeoutMs);
    function on(e) {
      if (e.source !== frame.contentWindow || !e.data || e.data.swarmlab !== 1 || e.data.event) return;
      const want = message && typeof message.id !== 'object' ? message.id : null;
      if (e.data.id !== want) return;
      clearTimeout(timer);
      removeEventListener('message', on);
      resolve(e.data);
    }
    addEventListener('message', on);
    frame.contentWindow.postMessage(message, APP_ORIGIN);
  });
}
// A raw message from the course page to its frame, and the reply with the same id (or null
// after timeoutMs). `build` runs in the page and returns the message (so it can hold what JSON
// cannot: a cycle); it goes in as the evaluated text itself, since the page's CSP allows no eval.
async function rpc(page, build, arg, timeoutMs = 20_000) {
  return page.evaluate(`(${postAndWait})((${build})(${JSON.stringify(arg)}), ${timeoutMs})`);
}
const call = (page, id, name, args) => rpc(page, ([id, name, args]) => ({ swarmlab: 1, id, call: name, args }), [id, name, args]);

const frameState = (frame) => frame.evaluate(() => window.swarmlab.state());
const menuItems = (frame) => frame.evaluate(() =>
  [...document.querySelectorAll('#parallel-dom [role="menuitem"], #parallel-dom [role="menuitemcheckbox"]')]
    .map((e) => e.getAttribute('aria-label') || e.textContent));

// The app's loop goes on: n more frames, or it sleeps with nothing left to change.
async function framesAdvance(frame, n = 3, timeoutMs = 20_000) {
  const f1 = await frame.evaluate(() => window.swarmlab.frames());
  return frame.waitForFunction((t) => window.swarmlab.frames() >= t || window.swarmlab.sleeping(), f1 + n, { timeout: timeoutMs })
    .then(() => true, () => false);
}

async function shoot(page, frame, file) {
  // The app has laid itself out at the frame's size, and drawn since.
  await frame.waitForFunction(() => {
    const d = window.swarmlab.state().display;
    return Math.abs(d.width - window.innerWidth) <= 1 && Math.abs(d.height - window.innerHeight) <= 1;
  }, null, { timeout: 20_000 }).catch(() => {});
  await framesAdvance(frame);
  const png = await page.screenshot({ path: join(outDir, file) });
  const img = await analysePng(png);
  console.log(`      ${file} ${img.width}x${img.height}: ${img.distinct} colours -> build/web-test/${file}`);
  return img;
}

async function main(url) {
  const tStart = Date.now();
  const appUrl = url;  // http://127.0.0.1:A/
  const coursePath = join(webDir, 'examples/course.html');
  if (!check('build/web/examples/course.html exists (copied by the build)', existsSync(coursePath))) return;
  const course = await serve({ '/course.html': readFileSync(coursePath, 'utf8') });
  // A page of a third origin embedding the very address the course page embeds.
  const embedAddress = `${appUrl}?embed&origins=${encodeURIComponent(course.origin)}`;
  const intruder = await serve({
    '/intruder.html': `<!doctype html><title>Not on the list</title>
<iframe id="swarmlab" src="${embedAddress}" style="width:640px;height:420px"></iframe>
<script>window.received = []; addEventListener('message', (e) => received.push({ origin: e.origin, data: e.data }));</script>`,
  });
  try {
    const context = await launchBrowser({ width: 1366, height: 768 });
    const blank = context.pages()[0];

    // 0. A link to the course page with a hostile ?app= (issue 36): nothing runs, the frame
    // stays empty, and the page says which address it refused and why. Its payloads would show
    // a dialog and mark the page (top.pwned); the dialogs are counted to the suite's end.
    const hostile = await context.newPage();
    if (blank) await blank.close();
    const dialogs = [];
    hostile.on('dialog', (d) => { dialogs.push(d.message()); d.dismiss().catch(() => {}); });
    const appPort = new URL(appUrl).port;
    const payloads = [
      ['javascript:alert(document.domain)//', /a javascript: address, and only http: and https: addresses are opened/],
      ['JaVaScRiPt:top.pwned=1;alert(1)', /a javascript: address/],
      [' javascript:top.pwned=1;alert(2)', /a javascript: address/],
      ['java\tscript:top.pwned=1;alert(3)', /a control character/],
      ['data:text/html,<script>top.pwned=1;alert(4)</script>', /a data: address/],
      ['blob:' + course.origin + '/0c6c1a4b-2b0e-4a4e-9a11-1c2d3e4f5a6b', /a blob: address/],
      ['file:///etc/passwd', /a file: address/],
      ['vbscript:msgbox(5)', /a vbscript: address/],
      [`http://student:secret@127.0.0.1:${appPort}/`, /a user name or password/],
      [`${appUrl}\n`, /a control character/],
      ['http://[not an address', /not a web address/],
    ];
    for (const [address, why] of payloads) {
      await hostile.goto(`${course.origin}/course.html?app=${encodeURIComponent(address)}`, { waitUntil: 'load' });
      const line = await hostile.waitForFunction(() => /does not open the app address/.test(document.getElementById('readout').textContent), null, { timeout: 10_000 })
        .then(() => hostile.textContent('#readout'), () => hostile.textContent('#readout'));
      const seen = await hostile.evaluate(() => ({ src: document.getElementById('swarmlab').getAttribute('src'), pwned: window.pwned === 1 }));
      const frames = hostile.frames().map((f) => f.url());
      check(`?app=${JSON.stringify(address).slice(0, 60)}: refused on the page, no frame address, nothing run`,
            why.test(line) && line.includes(JSON.stringify(address).slice(1, 20)) && await hostile.isVisible('#readout') &&
            seen.src === null && !seen.pwned && frames.length === 2 && frames[1] === 'about:blank',
            `"${line}"; src ${seen.src}; frames ${frames.join(' ')}; pwned ${seen.pwned}`);
    }
    // The Content-Security-Policy holds should a check ever let something through: no script
    // added to the page, no javascript: frame, no frame of another scheme; the browser reports
    // each refusal.
    const csp = await hostile.evaluate(() => new Promise((resolve) => {
      const refused = [];
      const done = () => resolve({ pwned: window.pwned === 1, injected: window.injected === true, refused });
      document.addEventListener('securitypolicyviolation', (e) => {
        refused.push(e.effectiveDirective);
        if (refused.filter((d) => d === 'script-src-elem').length === 2 && refused.includes('frame-src')) done();
      });
      const script = document.createElement('script');
      script.textContent = 'window.injected = true;';
      document.body.appendChild(script);
      const extra = document.createElement('iframe');
      extra.src = 'javascript:parent.pwned=1;alert(6)';
      document.body.appendChild(extra);
      document.getElementById('swarmlab').src = 'data:text/html,<p>framed</p>';
      setTimeout(done, 10_000);
    }));
    check('the course page\'s CSP refuses an injected inline script, a javascript: frame and a data: frame',
          !csp.pwned && !csp.injected && csp.refused.filter((d) => d === 'script-src-elem').length === 2 && csp.refused.includes('frame-src'),
          JSON.stringify(csp));
    await hostile.close();

    // 1. The course page on origin B embeds the app on origin A.
    const page = await context.newPage();
    watch(page, 'course');
    const t0 = Date.now();
    console.log(`      servers and browser up in ${((Date.now() - tStart) / 1000).toFixed(1)} s`);
    await page.goto(`${course.origin}/course.html?app=${encodeURIComponent(appUrl)}`, { waitUntil: 'load' });
    const frame = await appFrame(page, appUrl);
    if (!check('the course page embeds the app from another origin', frame !== null && course.origin !== new URL(appUrl).origin,
               `course ${course.origin}, app ${new URL(appUrl).origin}`)) return;
    const ready = await page.waitForFunction(() => !document.getElementById('load').disabled, null, { timeout: 30_000 })
      .then(() => true, () => false);
    check('the app tells the course page it is ready (its buttons come on)', ready,
          `${Date.now() - t0} ms; "${await page.textContent('#readout')}"`);
    const src = await page.getAttribute('#swarmlab', 'src');
    check('the frame\'s address asks for ?embed with the course page\'s origin on the list',
          src.includes('?embed&origins=') && decodeURIComponent(src).includes(course.origin), src);

    // The app runs under its own Content-Security-Policy, its inline script named by hash (a
    // policy that refused anything the app does would show as a console error, checked below).
    const appPolicy = await frame.evaluate(() => (document.querySelector('meta[http-equiv="Content-Security-Policy"]') || {}).content || '');
    const scriptSources = (/(?:^|; )script-src ([^;]*)/.exec(appPolicy) || [])[1];
    // 'unsafe-eval' beside 'wasm-unsafe-eval' for Safari 15, which knows only the former and
    // compiles no wasm without it (web/shell.html): still no script from anywhere else.
    check('the app in the frame runs under its CSP: scripts only its own files, its inline script by hash and its wasm',
          /^'self' 'wasm-unsafe-eval' 'unsafe-eval' 'sha256-[A-Za-z0-9+/]{43}='$/.test(scriptSources || ''), appPolicy);

    // 2. No menu bar, no welcome (this browser never saw the app: a first visit).
    await frame.waitForFunction(() => document.querySelectorAll('#parallel-dom .pdom-item').length >= 10, null, { timeout: 20_000 }).catch(() => {});
    const s0 = await frameState(frame);
    const pdomCount = await frame.evaluate(() => document.querySelectorAll('#parallel-dom .pdom-item').length);
    const menus0 = await menuItems(frame);
    check('embedded: no menu bar in the parallel DOM (no menu items) and none in state().menus',
          pdomCount >= 10 && menus0.length === 0 && s0.menus.length === 0 && s0.embed === true,
          `${pdomCount} mirrored items, menu items [${menus0.join(', ')}], state().embed ${s0.embed}`);
    const welcome = await call(page, 'w', 'welcomeShown', []);
    check('embedded: no welcome window on a first visit', welcome && welcome.result === false, JSON.stringify(welcome));
    const regions = await frame.evaluate(() => [...document.querySelectorAll('#parallel-dom .pdom-region')].map((e) => e.getAttribute('aria-label')));
    const buttons = await frame.evaluate(() => document.querySelectorAll('#parallel-dom button').length);
    // The frame is narrower than 1230 px: the compact layout, its panels in one drawer.
    check('embedded: the run and the panels stay (mirrored: the transport bar, the panels, the timeline)',
          ['Transport', 'Timeline'].every((r) => regions.includes(r)) && (regions.includes('Panels') || regions.includes('Controls')) &&
          buttons >= 10, `regions ${regions.join(', ')}; ${buttons} buttons`);
    await shoot(page, frame, 'embed-course-1366x768.png');

    // 3. The course page's buttons, as a teacher's student presses them.
    await page.click('#load');
    const loaded = await page.waitForFunction(() => /Loaded/.test(document.getElementById('readout').textContent), null, { timeout: 20_000 })
      .then(() => true, () => false);
    const s1 = await frameState(frame);
    check('"Load the hot wall": the reply says so and the app runs the preset', loaded && s1.name === HOT_WALL,
          `"${await page.textContent('#readout')}"; app runs "${s1.name}"`);
    // P and T once the wall has been hit (the app's own read-outs).
    const measured = await frame.waitForFunction(() => { const s = window.swarmlab.state(); return s.P !== null && s.T !== null; }, null, { timeout: 30_000 })
      .then(() => true, () => false);
    await page.click('#measure');
    const reading = await page.waitForFunction(() => /P = [-0-9.e+]+, T = [-0-9.e+]+/.test(document.getElementById('readout').textContent), null, { timeout: 20_000 })
      .then(() => page.textContent('#readout'), () => page.textContent('#readout'));
    const m = /P = ([-0-9.e+]+), T = ([-0-9.e+]+)/.exec(reading);
    check('"Read P and T": state() through the bridge gives the app\'s P and T as numbers',
          measured && m && Number(m[1]) > 0 && Number(m[2]) > 0 && reading.includes(HOT_WALL), `"${reading}"`);
    await page.click('#lesson');
    const opened = await page.waitForFunction(() => /Lesson/.test(document.getElementById('readout').textContent), null, { timeout: 20_000 })
      .then(() => true, () => false);
    const lesson = await frame.evaluate(() => window.swarmlab.lessonState());
    check('"Open the lesson": the app opens it and the reply gives its first step',
          opened && lesson && lesson.id === 'gas-at-the-wall' && lesson.step === 0,
          `"${await page.textContent('#readout')}"; app: ${lesson && lesson.id} step ${lesson && lesson.step}`);

    // 4. The message format: results, errors, order.
    const sLesson = await frameState(frame);
    const paused = await call(page, 'p', 'set', [{ playing: false }]);
    const after = await call(page, 17, 'state', []);
    check('set({playing: false}) replies with the state; a number id comes back as it was; calls run in order',
          paused && paused.result && paused.result.playing === false && after && after.id === 17 && after.result.playing === false,
          `${JSON.stringify(paused && paused.result && paused.result.playing)} ${JSON.stringify(after && after.result && after.result.playing)}`);
    await call(page, 'p2', 'set', [{ playing: true }]);
    const errors = [
      ['unknown call', () => ({ swarmlab: 1, id: 'e1', call: 'rmrf', args: [] }), /unknown call "rmrf" \(calls: ready, state/],
      ['an inherited name is no call', () => ({ swarmlab: 1, id: 'e2', call: 'constructor', args: [] }), /unknown call "constructor"/],
      ['too many arguments', () => ({ swarmlab: 1, id: 'e3', call: 'state', args: [1] }), /state takes 0 arguments, not 1/],
      ['a wrong argument', () => ({ swarmlab: 1, id: 'e4', call: 'set', args: ['fast'] }), /set: argument 1 must be an object, not "fast"/],
      ['args not an array', () => ({ swarmlab: 1, id: 'e5', call: 'seek', args: 3 }), /seek: args must be an array/],
      ['a key set() does not know', () => ({ swarmlab: 1, id: 'e6', call: 'set', args: [{ warp: 9 }] }), /swarmlab\.set\(\): unknown key "warp"/],
      ['a preset that fails validation', () => ({ swarmlab: 1, id: 'e7', call: 'load', args: [{ version: 1, name: 'bad', J: 1, particles: [{ m: -1, r: [0, 0, 0], v: [0, 0, 0] }], dt: 0.01, duration: 1 }] }), /must be > 0/],
      ['another version', () => ({ swarmlab: 2, id: 'e8', call: 'state' }), /not a version of the message format/],
      ['a bad id (answered with id null)', () => ({ swarmlab: 1, id: { a: 1 }, call: 'state' }), /id must be a string/],
      ['a 6-million-character payload', () => ({ swarmlab: 1, id: 'e9', call: 'load', args: ['x'.repeat(6_000_000)] }), /over \d+ characters of JSON, the limit/],
      ['a payload that is not JSON (a cycle)', () => { const a = []; a.push(a); return { swarmlab: 1, id: 'e10', call: 'load', args: [a] }; }, /not JSON data/],
      ['a lesson that does not exist', () => ({ swarmlab: 1, id: 'e11', call: 'openLesson', args: ['no-such-lesson'] }), /no-such-lesson/],
      // Indices that a 32-bit size_t or int would wrap (2^32 + 2 to 2), or a double not hold (2^53).
      ['select(2^32 + 2): out of range, not particle 2', () => ({ swarmlab: 1, id: 'e12', call: 'select', args: [4294967298] }),
       /^swarmlab\.select\(i\): i must be null or a particle index, an integer from 0 to \d+ \(\d+ of them\), not 4294967298$/],
      ['select(2^53): not a safe integer', () => ({ swarmlab: 1, id: 'e13', call: 'select', args: [2 ** 53] }),
       /^select: argument 1 must be an integer from 0 to 2\^53 - 1 or null, not 9007199254740992$/],
      ['screenPosition(2^32 + 1): out of range, not particle 1', () => ({ swarmlab: 1, id: 'e14', call: 'screenPosition', args: [2 ** 32 + 1] }),
       /^swarmlab\.screenPosition\(i\): i must be a particle index, an integer from 0 to \d+ \(\d+ of them\), not 4294967297$/],
    ];
    for (const [what, build, want] of errors) {
      const started = Date.now();
      const r = await rpc(page, build, null);
      check(`error reply: ${what}`, r !== null && typeof r.error === 'string' && want.test(r.error) && !('result' in r),
            r ? `${Date.now() - started} ms: "${String(r.error).slice(0, 140)}"` : 'no reply');
    }
    const s2 = await frameState(frame);
    check('the refused indices selected nothing', s2.selected === sLesson.selected, `${sLesson.selected} -> ${s2.selected}`);
    check('after the bad messages the app still runs the lesson\'s scene and the lesson', s2.name === sLesson.name &&
          (await frame.evaluate(() => window.swarmlab.lessonState().id)) === 'gas-at-the-wall', `"${s2.name}"`);
    check('the app keeps drawing after the bad messages', await framesAdvance(frame));

    // 4b. seek through the bridge: answered when it settles (the time reached), while the calls
    // after it go on at once: a second seek cancels the first, whose answer is its error; a
    // time beyond the run is refused with the rule.
    const tEnd = (await frameState(frame)).timeline.t_end;
    const near = Math.min(0.5, tEnd / 2);
    const [far, nearer] = await Promise.all([call(page, 's1', 'seek', [tEnd]), call(page, 's2', 'seek', [near])]);
    check('seek through the bridge: a second seek cancels the first (answered with its error)',
          far && /cancelled at t = /.test(far.error || ''), JSON.stringify(far));
    check('seek through the bridge: the second is answered with the time reached',
          nearer && typeof nearer.result === 'number' && Math.abs(nearer.result - near) < 0.02, JSON.stringify(nearer));
    const beyond = await call(page, 's3', 'seek', [1e9]);
    check('seek through the bridge: a time beyond the run is refused with the rule',
          beyond && /swarmlab\.seek\(t\): t = 1000000000 is beyond the run: t must be from 0 to the end/.test(beyond.error || ''),
          JSON.stringify(beyond));

    // 5. The embed flag both ways through the bridge: the menu bar comes back, and goes again.
    await call(page, 'm1', 'set', [{ embed: false }]);
    const back = await frame.waitForFunction(() => document.querySelectorAll('#parallel-dom [role="menuitem"]').length >= 3, null, { timeout: 20_000 })
      .then(() => true, () => false);
    const menus1 = await menuItems(frame);
    check('set({embed: false}): the menu bar is back (Scenario, View, Lessons, Help mirrored)',
          back && ['Scenario', 'View', 'Lessons', 'Help'].every((n) => menus1.includes(n)), menus1.join(', '));
    await call(page, 'm2', 'set', [{ embed: true }]);
    const gone = await frame.waitForFunction(() => document.querySelectorAll('#parallel-dom [role="menuitem"]').length === 0, null, { timeout: 20_000 })
      .then(() => true, () => false);
    check('set({embed: true}): the menu bar goes again', gone, (await menuItems(frame)).join(', '));

    // 6. A page on a third origin embedding the same address: no reply, no ready, no change.
    const other = await context.newPage();
    watch(other, 'intruder');
    await other.goto(`${intruder.origin}/intruder.html`, { waitUntil: 'load' });
    const otherFrame = await appFrame(other, appUrl);
    if (check('a page on a third origin embeds the same address', otherFrame !== null, intruder.origin)) {
      const before = await frameState(otherFrame);
      // The test (not the page) counts the messages the app's window has handled.
      await otherFrame.evaluate(() => { window.seen = 0; addEventListener('message', () => { window.seen++; }); });
      await other.evaluate(() => {
        const iframe = document.getElementById('swarmlab');
        const f = iframe.contentWindow, target = new URL(iframe.src).origin;
        f.postMessage({ swarmlab: 1, id: 'x1', call: 'load', args: [{ version: 1, name: 'Intruder', J: 0.001, particles: [{ m: 1, r: [0.1, 0, 0], v: [0, 0, 0] }, { m: 1, r: [-0.1, 0, 0], v: [0, 0, 0] }], dt: 0.01, duration: 5 }] }, target);
        f.postMessage({ swarmlab: 1, id: 'x2', call: 'set', args: [{ playing: false, embed: false }] }, target);
        f.postMessage({ swarmlab: 1, id: 'x3', call: 'state', args: [] }, target);
      });
      const handled = await otherFrame.waitForFunction(() => window.seen >= 3, null, { timeout: 20_000 }).then(() => true, () => false);
      // Anything the app sent in handling them was posted before this marker, and arrives first.
      await otherFrame.evaluate(() => parent.postMessage('marker', '*'));
      await other.waitForFunction(() => received.some((m) => m.data === 'marker'), null, { timeout: 20_000 }).catch(() => {});
      const received = await other.evaluate(() => received.map((m) => JSON.stringify(m.data)));
      check('a page not on the allow-list gets no reply and no ready message', handled && received.length === 1 && received[0] === '"marker"',
            `handled ${handled}; received [${received.join(', ')}]`);
      const after2 = await frameState(otherFrame);
      check('its calls change nothing (preset, play, embed)', after2.name === before.name && after2.name === DEFAULT &&
            after2.playing === before.playing && after2.embed === true,
            `"${after2.name}", playing ${after2.playing}, embed ${after2.embed}`);
      const warned = harness.consoleLog.some((l) => /was ignored: not in \?origins=/.test(l) && l.includes(intruder.origin));
      check('the app says on its console why it ignored them', warned);
    }
    await other.close();

    // 7. What a person sees: the course page at a phone's size too. A good call after the bad
    // ones takes their message off the app's page.
    const again = await call(page, 'l2', 'openLesson', ['gas-at-the-wall']);
    check('a good call after the bad ones is answered', again && again.result === true, JSON.stringify(again));
    await page.setViewportSize({ width: 390, height: 844 });
    await page.evaluate(() => document.getElementById('swarmlab').scrollIntoView());
    await shoot(page, frame, 'embed-course-390x844.png');
    const compact = await frameState(frame);
    check('on a phone the embedded app has no menu bar either', compact.menus.length === 0 && (await menuItems(frame)).length === 0,
          `layout ${compact.layout ?? ''}`);

    check('no dialog appeared on any course page (hostile ?app= included)', dialogs.length === 0, dialogs.join(' | '));
    check('no page errors', pageErrors.length === 0, pageErrors.join(' | '));
    check('no console errors', consoleErrors.length === 0, consoleErrors.slice(0, 5).join(' | '));
    console.log(`      the suite's browser part took ${((Date.now() - t0) / 1000).toFixed(1)} s`);
  } finally {
    await course.close();
    await intruder.close();
  }
}

runSuite('embed', 100_000, main);
