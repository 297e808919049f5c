// Touch and screen layouts of the browser app (issues 12 and 21), in headless Chromium with
// touch emulation and real touch and mouse events: on a phone's first visit a drag on the
// welcome scrolls it and never turns the camera, a tap on its close button closes it, a tap
// opens the Lessons menu and one outside closes it; a tap selects a particle, a tap on empty
// space deselects without turning the camera, one finger orbits, two fingers pinch to zoom
// and slide the view, a finger drags a panel's content without editing what it started on,
// also across a stalled frame; the timeline drags by touch at once and a quick mouse drag on
// it ends under the pointer; a whiteboard's press with no motion before it selects;
// swarmlab.set() refuses what it does not know; and at the six classroom screen sizes (and
// 1280x720 at UI scale 1.5) every panel lies inside the canvas, none over another or over the
// 3D view, with a screenshot of each in build/web-test/.
// Run through tests/web/run.sh; the last line is "N passed, M failed".
import * as harness from './harness.mjs';

import { join } from 'node:path';

const { check, openApp, launchBrowser, runSuite, keepsDrawing, outDir, pageErrors, consoleErrors, until } = harness;

const api = (page, fn, arg) => page.evaluate(fn, arg);
const appState = (page) => api(page, () => window.swarmlab.state());

const inside = (r, W, H) => r.x >= -0.5 && r.y >= -0.5 && r.x + r.width <= W + 0.5 && r.y + r.height <= H + 0.5;
const overlap = (a, b) => a.x + 0.5 < b.x + b.width && b.x + 0.5 < a.x + a.width &&
                          a.y + 0.5 < b.y + b.height && b.y + 0.5 < a.y + a.height;
const within = (p, r) => p.x >= r.x && p.x < r.x + r.width && p.y >= r.y && p.y < r.y + r.height;

// Fingers through the DevTools protocol along straight paths, an event every 16 ms of the
// hand's own time (the app judges gestures by the events' times, however many of them a
// frame takes in). The caller waits for what the gesture should do.
async function fingers(cdp, paths, steps = 5) {
  const at = (k) => paths.map(([x0, y0, x1, y1], id) => ({ x: x0 + (x1 - x0) * k / steps, y: y0 + (y1 - y0) * k / steps, id }));
  const stamp = handClock();
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: at(0), timestamp: stamp() });
  for (let k = 1; k <= steps; ++k)
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: at(k), timestamp: stamp() });
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [], timestamp: stamp() });
}

// The times a hand's touch events carry (CDP's timestamp becomes the event's timeStamp): one
// every 16 ms from now, however long this busy machine takes to send them. The app judges a
// hold by these times, as it does a real finger's.
function handClock(stepMs = 16) {
  let t = Date.now() / 1000 - stepMs / 1000;
  return () => (t += stepMs / 1000);
}

// Until the app has laid the canvas out at W x H and the layout holds (the heights it measured
// are the ones it used).
const settledAt = (page, W, H) => until(page, (st, a) => st.display.width === a.W && st.display.height === a.H && st.layout_settled, { W, H });

// Where the app drew what a person presses, found by name from what it reports: a menu's title
// in the bar, a floating window or its close button, the timeline's bar, a panel. The one place
// tests look targets up; the parallel DOM will replace it with getByRole.
async function findTarget(page, kind, name) {
  const s = await appState(page);
  const byName = (list) => (list || []).find((e) => e.name === name || (name instanceof RegExp && name.test(e.name)));
  switch (kind) {
    case 'menu': return byName(s.menus) || null;
    case 'window': return byName(s.windows) || null;
    case 'close': return byName(s.windows)?.close || null;
    case 'timeline': return s.timeline;
    case 'panel': return byName(s.panels) || null;
  }
  return null;
}
const centre = (r) => ({ x: r.x + r.width / 2, y: r.y + r.height / 2 });

// One finger along path ([[x, y], ...]) through the DevTools protocol, an event every 16 ms
// of the hand's own time: the app tells gestures apart by the events' own times.
async function drag(cdp, path) {
  const at = ([x, y]) => [{ x, y, id: 1 }];
  const stamp = handClock();
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: at(path[0]), timestamp: stamp() });
  for (const p of path.slice(1))
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: at(p), timestamp: stamp() });
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [], timestamp: stamp() });
}
const line = (x0, y0, x1, y1, n = 8) => Array.from({ length: n + 1 }, (_, k) => [x0 + (x1 - x0) * k / n, y0 + (y1 - y0) * k / n]);
const sameCamera = (a, b) => a.yaw === b.yaw && a.pitch === b.pitch;
const cameraText = (c) => `yaw ${c.yaw.toFixed(4)}, pitch ${c.pitch.toFixed(4)}`;

// A first visit on a phone: the welcome floats over the view. A drag on it scrolls it and never
// turns the camera; its close button closes it; the Lessons menu opens by a tap, and a tap
// outside closes it without touching the view.
async function welcomeOnPhone(url, context) {
  const first = await context.newPage();
  harness.watch(first, 'welcome');
  await first.setViewportSize({ width: 390, height: 844 });
  await first.goto(url + '?welcome', { waitUntil: 'load' });
  await first.waitForFunction(() => window.swarmlab && window.swarmlab.firstFrameMs !== null && window.swarmlab.welcomeShown(),
                              null, { timeout: 30_000 }).catch(() => {});
  const page = first;
  await settledAt(page, 390, 844);
  let s = await until(page, (st) => st.windows && st.windows.some((w) => w.name === 'Welcome'));
  if (!check('390x844 first visit: the welcome floats over the view', await api(page, () => window.swarmlab.welcomeShown()) &&
             !!(await findTarget(page, 'window', 'Welcome')), JSON.stringify(s.windows))) return;
  await page.screenshot({ path: join(outDir, 'touch-welcome-390x844.png') });
  console.log('      screenshot -> build/web-test/touch-welcome-390x844.png');
  const cdp = await context.newCDPSession(page);

  // A drag on the welcome (up and sideways over its text) scrolls it; the camera stays.
  const welcome = await findTarget(page, 'window', 'Welcome');
  const camera0 = s.camera, selected0 = s.selected;
  const mid = centre(welcome);
  await drag(cdp, line(mid.x - 60, mid.y + 120, mid.x + 60, mid.y - 80));
  s = await until(page, (st) => st.fingers === 0 && st.windows.some((w) => w.name === 'Welcome' && w.scroll > 0));
  const scrolled = (s.windows.find((w) => w.name === 'Welcome') || {}).scroll;
  check('a drag on the welcome scrolls it', scrolled > 0, `scroll ${scrolled}`);
  check('... and does not turn the camera (nothing passes through to the view)', sameCamera(s.camera, camera0),
        `${cameraText(camera0)} -> ${cameraText(s.camera)}`);
  check('... nor select anything', s.selected === selected0, `selected ${selected0} -> ${s.selected}`);

  // A tap on its close button closes it.
  const close = await findTarget(page, 'close', 'Welcome');
  check('the welcome\'s close button is at least 44 CSS px square', close && close.width >= 44 && close.height >= 44,
        close ? `${close.width.toFixed(1)}x${close.height.toFixed(1)}` : 'no close button');
  if (close) {
    const c = centre(close);
    await page.touchscreen.tap(c.x, c.y);
    s = await until(page, (st) => !st.windows.some((w) => w.name === 'Welcome'));
  }
  check('a tap on the welcome\'s close button closes it', !(await api(page, () => window.swarmlab.welcomeShown())),
        JSON.stringify(s.windows.map((w) => w.name)));
  check('... and the camera stayed', sameCamera(s.camera, camera0), `${cameraText(camera0)} -> ${cameraText(s.camera)}`);

  // The Lessons menu opens by a tap on its title, at least 44 px tall.
  const lessons = await findTarget(page, 'menu', 'Lessons');
  check('the menu bar shows Lessons, at least 44 CSS px tall', lessons && lessons.height >= 44,
        lessons ? `${lessons.width.toFixed(0)}x${lessons.height.toFixed(0)}` : JSON.stringify(s.menus));
  if (lessons) {
    const c = centre(lessons);
    await page.touchscreen.tap(c.x, c.y);
    s = await until(page, (st) => st.windows.some((w) => /^##Menu/.test(w.name)));
    const menu = await findTarget(page, 'window', /^##Menu/);
    check('a tap on Lessons opens its menu', !!menu, JSON.stringify(s.windows.map((w) => w.name)));
    await page.screenshot({ path: join(outDir, 'touch-lessons-menu-390x844.png') });
    console.log('      screenshot -> build/web-test/touch-lessons-menu-390x844.png');
    // A tap on the view beside the menu closes it and leaves the camera and selection alone.
    const spot = { x: s.view.x + s.view.width - 20, y: s.view.y + s.view.height - 20 };
    await page.touchscreen.tap(spot.x, spot.y);
    s = await until(page, (st) => !st.windows.some((w) => /^##Menu/.test(w.name)));
    check('a tap outside the open menu closes it', !s.windows.some((w) => /^##Menu/.test(w.name)),
          JSON.stringify(s.windows.map((w) => w.name)));
    check('... without selecting or turning anything behind it', s.selected === selected0 && sameCamera(s.camera, camera0),
          `selected ${s.selected}, ${cameraText(s.camera)}`);
  }
  await cdp.detach();
  await page.close();
}

// The timeline drags by touch at once: a finger that lands on the bar and moves straight away
// scrubs (no hold), and the run ends at the time under the finger where it lifted.
async function timelineByTouch(page, context) {
  await api(page, () => window.swarmlab.set({ playing: true, speed: 4 }));
  let s = await until(page, (st) => st.t_reached >= Math.min(3, 0.8 * st.timeline.t_end));
  await api(page, () => window.swarmlab.set({ playing: false }));
  s = await until(page, (st) => !st.playing);
  const bar = await findTarget(page, 'timeline');
  check('the timeline\'s bar is at least 44 CSS px tall', bar && bar.height >= 44, bar ? `${bar.width.toFixed(0)}x${bar.height.toFixed(0)}` : 'none');
  if (!bar) return;
  const xAt = (t) => bar.x + bar.width * t / bar.t_end;
  const tFrom = s.t_reached * 0.9, tTo = s.t_reached * 0.3;
  const y = bar.y + bar.height / 2;
  const camera0 = s.camera;
  const cdp = await context.newCDPSession(page);
  await drag(cdp, line(xAt(tFrom), y, xAt(tTo), y, 6));
  await cdp.detach();
  const expected = s.t_reached * 0.3;
  const dt = JSON.parse(await api(page, () => window.swarmlab.preset())).dt;
  // The bar's pixel is bar.t_end / bar.width wide in time: the finger lands within one.
  const tolerance = bar.t_end / bar.width + dt;
  s = await until(page, (st, a) => st.fingers === 0 && Math.abs(st.t - a.expected) <= a.tolerance, { expected, tolerance });
  check('a finger dragged along the timeline at once scrubs it to the time under the finger',
        Math.abs(s.t - expected) <= tolerance, `expected t = ${expected.toFixed(3)} +- ${tolerance.toFixed(3)}, got ${s.t.toFixed(3)}`);
  check('... and does not turn the camera', sameCamera(s.camera, camera0), `${cameraText(camera0)} -> ${cameraText(s.camera)}`);
}

// An interactive whiteboard (or a touchscreen acting as a mouse) presses at a new place with no
// mouse motion before it: the press selects the particle there and never turns the camera.
async function whiteboardClick(page, context) {
  await api(page, () => window.swarmlab.set({ playing: false, selected: null }));
  let s = await until(page, (st) => st.selected === null);
  const cdp = await context.newCDPSession(page);
  // The mouse was last somewhere else: over a panel, far from the particle.
  const panel = s.panels[0];
  await page.mouse.move(panel.x + panel.width / 2, panel.y + panel.height / 2);
  s = await until(page, (st) => st.touch === false);  // the app has taken the mouse
  const camera0 = s.camera;
  const p = await api(page, () => window.swarmlab.screenPosition(1));
  const press = { x: p.x, y: p.y, button: 'left', clickCount: 1 };
  await cdp.send('Input.dispatchMouseEvent', { type: 'mousePressed', ...press });
  await cdp.send('Input.dispatchMouseEvent', { type: 'mouseReleased', ...press });
  s = await until(page, (st) => st.selected === 1);
  check('a whiteboard press with no motion before it selects the particle there', s.selected === 1,
        `pressed (${p.x.toFixed(0)}, ${p.y.toFixed(0)}), selected ${s.selected}`);
  check('... and does not turn the camera', sameCamera(s.camera, camera0), `${cameraText(camera0)} -> ${cameraText(s.camera)}`);
  await cdp.detach();
  await api(page, () => window.swarmlab.set({ selected: null }));
}

// A quick mouse drag along the timeline, moved and let go at once: the run ends at the time
// under the pointer where the button was let go (finding 12: it ended at 8.13 with the pointer
// at 2.65).
async function timelineByMouse(page) {
  let s = await appState(page);
  const bar = await findTarget(page, 'timeline');
  if (!bar) return;
  const xAt = (t) => bar.x + bar.width * t / bar.t_end;
  const y = bar.y + bar.height / 2;
  const tTo = 0.25 * s.t_reached;
  await page.mouse.move(xAt(0.85 * s.t_reached), y);
  await page.mouse.down();
  await page.mouse.move(xAt(tTo), y);
  await page.mouse.up();
  const dt = JSON.parse(await api(page, () => window.swarmlab.preset())).dt;
  const tolerance = bar.t_end / bar.width + dt;
  s = await until(page, (st, a) => Math.abs(st.t - a.tTo) <= a.tolerance, { tTo, tolerance });
  check('a quick mouse drag on the timeline ends at the time under the pointer', Math.abs(s.t - tTo) <= tolerance,
        `pointer over t = ${tTo.toFixed(3)} +- ${tolerance.toFixed(3)}, run at ${s.t.toFixed(3)}`);
}

async function gestures(page, context) {
  await api(page, () => window.swarmlab.set({ playing: false }));
  let s = await settledAt(page, 1024, 768);
  check('state() has the camera, layout, UI scale, view and panels',
        typeof s.camera?.distance === 'number' && typeof s.camera.yaw === 'number' && typeof s.camera.pitch === 'number' &&
        typeof s.layout === 'string' && s.ui_scale === 1 && s.view?.width > 0 && Array.isArray(s.panels) && s.panels.length >= 2,
        `layout ${s.layout}, view ${JSON.stringify(s.view)}, panels ${s.panels.map((p) => p.name).join(', ')}`);
  check('a 1024x768 tablet gets the compact landscape layout', s.layout === 'landscape', s.layout);

  // A tap on a particle selects it and leaves the camera where it was.
  const p0 = await api(page, () => window.swarmlab.screenPosition(0));
  const yaw0 = s.camera.yaw;
  await page.touchscreen.tap(p0.x, p0.y);
  s = await until(page, (st) => st.selected === 0);
  check('a tap on a particle selects it', s.selected === 0, `tapped (${p0.x.toFixed(0)}, ${p0.y.toFixed(0)}), selected ${s.selected}`);
  check('the tap did not turn the camera', s.camera.yaw === yaw0, `yaw ${yaw0} -> ${s.camera.yaw}`);

  // A tap on empty space (a corner of the view, far from every particle) deselects, no spin.
  const count = (await api(page, () => JSON.parse(window.swarmlab.preset()))).particles?.masses?.length ?? 4;
  const positions = await api(page, (n) => Array.from({ length: n }, (_, i) => window.swarmlab.screenPosition(i)), count);
  const empty = { x: s.view.x + 25, y: s.view.y + s.view.height - 25 };
  const far = positions.every((p) => !p || Math.hypot(p.x - empty.x, p.y - empty.y) > 80);
  await page.touchscreen.tap(empty.x, empty.y);
  s = await until(page, (st) => st.selected === null);
  check('a tap on empty space deselects', far && s.selected === null, `selected ${s.selected}, far from particles: ${far}`);
  check('... without turning the camera', s.camera.yaw === yaw0, `yaw ${yaw0} -> ${s.camera.yaw}`);

  const cdp = await context.newCDPSession(page);
  const cx = s.view.x + s.view.width / 2, cy = s.view.y + s.view.height / 2;
  // Each gesture is waited on until the app has seen its last finger lift and what it changed.
  // One finger dragged across the view orbits.
  await fingers(cdp, [[cx - 80, cy, cx + 80, cy]]);
  let t = await until(page, (st, yaw) => st.fingers === 0 && st.camera.yaw !== yaw, yaw0);
  check('one finger dragged on the view orbits (yaw changes)', Math.abs(t.camera.yaw - yaw0) > 0.3,
        `yaw ${yaw0.toFixed(3)} -> ${t.camera.yaw.toFixed(3)}`);
  check('... and selects nothing', t.selected === null);

  // Two fingers spreading apart zoom in; pinching them together zooms out.
  const d0 = t.camera.distance, yaw1 = t.camera.yaw;
  await fingers(cdp, [[cx - 40, cy, cx - 120, cy], [cx + 40, cy, cx + 120, cy]]);
  t = await until(page, (st, d) => st.fingers === 0 && st.camera.distance !== d, d0);
  check('two fingers spread apart zoom in (distance / 3)', Math.abs(t.camera.distance / d0 - 1 / 3) < 0.05,
        `distance ${d0.toFixed(3)} -> ${t.camera.distance.toFixed(3)}`);
  check('... without orbiting', t.camera.yaw === yaw1);
  const d1 = t.camera.distance;
  await fingers(cdp, [[cx - 120, cy, cx - 40, cy], [cx + 120, cy, cx + 40, cy]]);
  t = await until(page, (st, d) => st.fingers === 0 && st.camera.distance !== d, d1);
  check('a pinch zooms out again', Math.abs(t.camera.distance / d1 - 3) < 0.15, `distance ${d1.toFixed(3)} -> ${t.camera.distance.toFixed(3)}`);

  // Two fingers dragged together slide the scene with them, and it stays slid while the view
  // follows the centre of mass. Particles nearer or farther than the centre move a little more
  // or less than the fingers (perspective), so their mean is compared.
  const seenAt = () => api(page, (n) => Array.from({ length: n }, (_, i) => window.swarmlab.screenPosition(i)), count);
  const beforePan = await seenAt(), yaw2 = t.camera.yaw, d2 = t.camera.distance;
  const [dx, dy] = [90, 50];
  await fingers(cdp, [[cx - 60, cy, cx - 60 + dx, cy + dy], [cx + 60, cy, cx + 60 + dx, cy + dy]]);
  await until(page, (st, p) => st.fingers === 0 && JSON.stringify(window.swarmlab.screenPosition(0)) !== p, JSON.stringify(beforePan[0]));
  const held = await keepsDrawing(page);  // it stays slid over the frames after
  const afterPan = await seenAt();
  const mean = (k) => afterPan.reduce((sum, p, i) => sum + p[k] - beforePan[i][k], 0) / count;
  t = await appState(page);
  check('two fingers dragged together slide the scene with them', Math.abs(mean('x') / dx - 1) < 0.3 && Math.abs(mean('y') / dy - 1) < 0.3 && held.ok,
        `fingers moved (${dx}, ${dy}) px, particles by (${mean('x').toFixed(1)}, ${mean('y').toFixed(1)}) on average ${held.detail} later`);
  check('... without orbiting or zooming', t.camera.yaw === yaw2 && Math.abs(t.camera.distance / d2 - 1) < 0.02,
        `yaw ${yaw2.toFixed(3)} -> ${t.camera.yaw.toFixed(3)}, distance ${d2.toFixed(3)} -> ${t.camera.distance.toFixed(3)}`);

  // A finger dragged up the controls scrolls them, and presses nothing it started on.
  const controls = t.panels.find((p) => p.name === 'Controls');
  if (check('the controls are a panel of the drawer', !!controls, JSON.stringify(t.panels.map((p) => p.name)))) {
    const x = controls.x + controls.width / 2, y0 = controls.y + controls.height * 0.75;
    await fingers(cdp, [[x, y0, x, y0 - controls.height * 0.5]], 6);
    t = await until(page, (st, a) => st.fingers === 0 && st.panels.some((p) => p.name === 'Controls' && p.scroll !== a), controls.scroll);
    const after = t.panels.find((p) => p.name === 'Controls');
    const field = await api(page, () => !!document.querySelector('#parallel-dom input.pdom-editing'));
    check('a finger dragged on the controls scrolls them', after && after.scroll > 0.3 * controls.height * 0.5,
          `scroll ${controls.scroll} -> ${after && after.scroll.toFixed(1)} px`);
    check('... without editing anything (no field open, preset unchanged)', !field && t.edited === false && t.name === s.name,
          `field open: ${field}, edited: ${t.edited}`);

    // The page stalls for 0.6 s (a slow frame on a busy Chromebook) between the finger landing
    // and its first move 30 ms later: the move's own time says drag, so it scrolls back up.
    const scrolled = after.scroll, yDown = controls.y + controls.height * 0.3;
    const t0 = Date.now() / 1000;
    const touch = (type, y, dt) => cdp.send('Input.dispatchTouchEvent', { type, touchPoints: type === 'touchEnd' ? [] : [{ x, y, id: 1 }], timestamp: t0 + dt });
    await touch('touchStart', yDown, 0);
    await api(page, () => { const end = performance.now() + 600; while (performance.now() < end) { /* a stalled frame */ } });
    await touch('touchMove', yDown + 60, 0.03);
    await touch('touchMove', yDown + 150, 0.06);
    await touch('touchEnd', yDown + 150, 0.09);
    t = await until(page, (st, a) => st.fingers === 0 && st.panels.some((p) => p.name === 'Controls' && p.scroll < a - 100), scrolled);
    const back = t.panels.find((p) => p.name === 'Controls');
    const open = await api(page, () => { const e = document.getElementById('swarmlab-number'); return e && !e.hidden; });
    check('a drag across a stalled frame still scrolls, pressing nothing', back && back.scroll < scrolled - 100 && !open && t.edited === false,
          `scroll ${scrolled.toFixed(1)} -> ${back && back.scroll.toFixed(1)} px, field open: ${open}, edited: ${t.edited}`);
  }
  await cdp.detach();

  // swarmlab.set(): each key changes what it names; anything else throws naming it.
  const errors = await api(page, () => ['{"bogus": 1}', '{"speed": -2}', '{"layout": "tiny"}', '{"playing": "yes"}', '{"ui_scale": 9}']
    .map((j) => { try { window.swarmlab.set(JSON.parse(j)); return null; } catch (e) { return e.message; } }));
  check('set() refuses an unknown key, naming it', /bogus/.test(errors[0] || ''), errors[0]);
  check('set() refuses bad values, naming the key', /speed/.test(errors[1] || '') && /layout/.test(errors[2] || '') &&
        /playing/.test(errors[3] || '') && /ui_scale/.test(errors[4] || ''), errors.slice(1).join(' | '));
  t = await api(page, () => window.swarmlab.set({ speed: 2, playing: true, selected: 1 }));
  check('set() changes speed, playing and selected', t.speed === 2 && t.playing === true && t.selected === 1,
        `speed ${t.speed}, playing ${t.playing}, selected ${t.selected}`);
  await api(page, () => window.swarmlab.set({ playing: false, selected: null }));
}

// Every panel inside the canvas, none over another or over the view; the particles drawn in
// the view, none under the read-outs.
async function checkLayout(page, W, H, label, expect) {
  await page.setViewportSize({ width: W, height: H });
  const s = await settledAt(page, W, H);
  const parts = [...s.panels, { name: 'view', ...s.view }];
  const outside = parts.filter((p) => !inside(p, W, H)).map((p) => p.name);
  const clashes = [];
  for (let i = 0; i < parts.length; ++i)
    for (let j = i + 1; j < parts.length; ++j)
      if (overlap(parts[i], parts[j])) clashes.push(`${parts[i].name}/${parts[j].name}`);
  check(`${label}: layout ${expect}`, s.layout === expect, s.layout);
  check(`${label}: every panel and the view inside the canvas`, outside.length === 0, outside.join(', ') ||
        parts.map((p) => `${p.name} ${Math.round(p.x)},${Math.round(p.y)} ${Math.round(p.width)}x${Math.round(p.height)}`).join('; '));
  check(`${label}: no panel over another or over the view`, clashes.length === 0, clashes.join(', '));
  check(`${label}: the view keeps room (>= 40% of the width, 1/3 of the height)`,
        s.view.width >= 0.4 * W && s.view.height >= H / 3, `${Math.round(s.view.width)}x${Math.round(s.view.height)}`);
  const positions = await api(page, () => [0, 1, 2, 3].map((i) => window.swarmlab.screenPosition(i)));
  const readouts = s.panels.find((p) => p.name === 'Read-outs');
  const shown = positions.filter(Boolean);
  check(`${label}: every particle drawn in the view, none under the read-outs`,
        shown.length === 4 && shown.every((p) => within(p, s.view) && !(readouts && within(p, readouts))),
        `${shown.length} of 4 on screen`);
  await page.screenshot({ path: join(outDir, `touch-${label}.png`) });
  console.log(`      screenshot -> build/web-test/touch-${label}.png`);
  return s;
}

async function main(url) {
  const context = await launchBrowser({ width: 1024, height: 768, hasTouch: true, isMobile: true });
  await welcomeOnPhone(url, context);  // first: the welcome shows on the profile's first visit only
  const blank = context.pages()[0];
  const { page, started, error } = await openApp(url, 'touch');
  if (blank) await blank.close();
  if (!check('the app starts on a touch tablet', started, error || '')) return;
  await gestures(page, context);
  await timelineByTouch(page, context);
  await whiteboardClick(page, context);
  await timelineByMouse(page);

  const sizes = [[390, 844, 'portrait'], [844, 390, 'landscape'], [1024, 768, 'landscape'],
                 [1366, 768, 'wide'], [1280, 720, 'wide'], [1920, 1080, 'wide']];
  for (const [W, H, kind] of sizes) await checkLayout(page, W, H, `${W}x${H}`, kind);
  // A projector at UI scale 1.5: compact, and the view still the larger part of the window.
  await api(page, () => window.swarmlab.set({ ui_scale: 1.5 }));
  const big = await checkLayout(page, 1280, 720, '1280x720-scale1.5', 'landscape');
  check('UI scale 1.5 applied', big.ui_scale === 1.5, String(big.ui_scale));
  check('1280x720 at UI scale 1.5: the view keeps half the width', big.view.width >= 640, `${Math.round(big.view.width)} px`);
  await api(page, () => window.swarmlab.set({ ui_scale: 1, layout: 'compact' }));
  const compact = await until(page, (st) => st.layout === 'landscape');
  check('set({layout: "compact"}) overrides the wide layout at 1280x720', compact.layout === 'landscape', compact.layout);

  check('no page errors', pageErrors.length === 0, pageErrors.join(' | '));
  check('no console errors', consoleErrors.length === 0, consoleErrors.join(' | '));
}

runSuite('touch_e2e', 140_000, main);
