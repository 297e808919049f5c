// A lost WebGL context is survived (issue 26). Phones, tablets and Chromebooks drop the GPU
// context when the GPU resets, memory runs short or a tab stays long in the background. Here a
// student changes the gas's max speed through the parallel DOM (typed into its field with the
// keyboard) and plays the run; then the fault is injected (WEBGL_lose_context.loseContext(), the one call
// into the page that a person does not make): the message line says so in one calm line, the
// fatal overlay stays away, and the run waits where it was; then restoreContext(): the line
// goes, the live region says the picture is back, the canvas draws the particles again, the
// clock goes on from where it stopped, and the student's max speed is still there. Four times on one
// page: at a laptop's 1366x768 and a phone's 390x844, in the dark theme and then in the light
// one (View > Light theme, as a person sets it). No page error, no console error, and no WebGL
// warning (an INVALID_OPERATION is one) but the single line loseContext() itself writes.
// Screenshots before the loss, during it and after the restore: build/web-test/context/.
// window.swarmlab is only read. Run through tests/web/run.sh; the last line is "N passed, M failed".
import { mkdirSync } from 'node:fs';
import { join } from 'node:path';
import * as harness from './harness.mjs';
import { person } from './person.mjs';

const { check, openApp, launchBrowser, runSuite, outDir, pageErrors, consoleErrors, consoleLog, screenshot,
        clockAdvances, shipped, base64url } = harness;

const shotDir = join(outDir, 'context');
const LOST = 'The picture is paused while the browser restarts its graphics. Your run and your changes are kept.';
const BACK = 'The picture is back.';
const SIZES = [[1366, 768], [390, 844]];
const FIELD = 'max speed';
const EDITED_SPEED = 1.5;  // the swarm's max speed as the student types it (the preset's is 1)
// The gas of Fig. 4 (4000 particles in a sphere), for long enough that the run never ends while
// the suite looks (200 at a speed of 1.26 a second; a much longer run is refused as too large):
// the view is full of particles, so its colours are the renderer's own.
const PRESET = { ...shipped('fig4-equilibration.json'), duration: 200 };
// A WebGL complaint in the console: an error of a call (INVALID_OPERATION: a name of the lost
// context used on the new one, ...) or WebGL's own words. The line loseContext() may write
// itself (the fault being injected) is not one; nor is the driver's performance note about a
// screenshot's ReadPixels.
const COMPLAINT = /INVALID_|WebGL: /;
const INJECTED = /WebGL: CONTEXT_LOST_WEBGL: loseContext: context lost/;

const appState = (page) => page.evaluate(() => window.swarmlab.state());
const maxSpeed = (page) => page.evaluate(() => JSON.parse(window.swarmlab.preset()).particles.velocity.speed);
const noticeNow = (page) => page.evaluate(() => {
  const n = document.getElementById('notice');
  return { shown: !n.hidden, text: document.getElementById('notice-text').textContent, kind: n.className,
           live: n.getAttribute('aria-live'),
           overlay: !document.getElementById('overlay').classList.contains('hidden'),
           error: window.swarmlabError || null };
});

// The 3D view's upper 70 %, as analysePng measures it (x0, y0, x1, y1 in CSS pixels): the
// particles' colours (the Turbo map of their speeds), above the colour legend at the view's
// foot, which ImGui draws and would be there without them.
const viewRect = (s) => ({ view: [Math.round(s.view.x), Math.round(s.view.y),
                                  Math.round(s.view.x + s.view.width), Math.round(s.view.y + 0.7 * s.view.height)] });
// Drawn: not black, and the particles' colours in the view.
const drawn = (img) => img.blackShare < 0.5 && img.vivid.view >= 500;

// A screenshot into build/web-test/context/, the message line as the person sees it.
const shoot = (page, file, rects, until = null) => screenshot(page, join('context', file), rects, until, true);

// The app has laid itself out at W x H (what a resize should give).
async function laidOut(page, W, H) {
  await page.waitForFunction(([w, h]) => {
    const s = window.swarmlab.state();
    return s.display.width === w && s.display.height === h && s.layout_settled;
  }, [W, H], { timeout: 30_000 }).catch(() => {});
  return appState(page);
}

async function lostAndRestored(page, W, H, theme) {
  const label = `${W}x${H} ${theme}`;
  const name = `${W}x${H}-${theme}`;
  await page.setViewportSize({ width: W, height: H });
  const s = await laidOut(page, W, H);
  check(`${label}: laid out`, s.display.width === W && s.display.height === H, JSON.stringify(s.display));
  check(`${label}: the run plays`, s.playing === true);
  const rects = viewRect(s);

  const before = await shoot(page, `context-${name}-1-before.png`, rects, drawn);
  check(`${label}: before the loss the view shows the particles`, drawn(before), `vivid ${before.vivid.view}`);

  // The fault: the GPU context is taken away.
  await page.evaluate(() => {
    const gl = document.getElementById('canvas').getContext('webgl2');
    window.contextFault = gl.getExtension('WEBGL_lose_context');
    window.contextFault.loseContext();
  });
  await page.waitForFunction((t) => !document.getElementById('notice').hidden &&
                             document.getElementById('notice-text').textContent === t, LOST, { timeout: 20_000 })
    .catch(() => {});
  const lost = await noticeNow(page);
  check(`${label}: lost: the message line says so calmly`, lost.shown && lost.text === LOST && lost.kind === 'context',
        `"${lost.text}" (${lost.kind})`);
  check(`${label}: lost: the line is a live region (a screen reader says it)`, lost.live === 'polite');
  check(`${label}: lost: no "cannot start" overlay, no error`, !lost.overlay && !lost.error, lost.error || '');
  const tLost = await page.evaluate(() => window.swarmlab.time());
  const during = await shoot(page, `context-${name}-2-lost.png`, rects);
  const tStill = await page.evaluate(() => window.swarmlab.time());
  check(`${label}: lost: the run waits where it was`, tStill === tLost, `t ${tLost} -> ${tStill}`);
  check(`${label}: lost: the message line stays while the picture is away`, (await noticeNow(page)).shown);
  // Nothing can be drawn: the frame loop asks for no animation frame until the context is back.
  const asleep = await page.waitForFunction(() => window.swarmlab.sleeping(), null, { timeout: 10_000 }).then(() => true, () => false);
  check(`${label}: lost: the frame loop sleeps`, asleep);

  // The browser gives the context back.
  const restoredAt = Date.now();
  const heard = await page.evaluate(() => window.liveRegionSaid.length);
  await page.evaluate(() => window.contextFault.restoreContext());
  await page.waitForFunction(([t, from]) => document.getElementById('notice').hidden &&
                             window.liveRegionSaid.slice(from).includes(t), [BACK, heard], { timeout: 20_000 })
    .catch(() => {});
  const back = await noticeNow(page);
  const said = await page.evaluate((from) => window.liveRegionSaid.slice(from), heard);
  check(`${label}: restored: the line goes and the live region says the picture is back`,
        !back.shown && said.includes(BACK), `notice ${back.shown ? 'shown' : 'hidden'}, live region since: ${JSON.stringify(said)}`);
  // As before the loss: the particles' colours in the view, about as many (the page's own
  // overlay, were it shown, has a few vivid pixels of its own, far fewer).
  const again = (img) => drawn(img) && img.vivid.view >= 0.5 * before.vivid.view;
  const after = await shoot(page, `context-${name}-3-restored.png`, rects, again);
  check(`${label}: restored: the canvas draws the particles again`, again(after),
        `vivid ${after.vivid.view} (before ${before.vivid.view}, lost ${during.vivid.view}), black ${(100 * after.blackShare).toFixed(1)}%`);
  // From where it stopped: neither started again nor moved on while away (at most the run's
  // speed times the wall time since the restore).
  const t0 = await page.evaluate(() => window.swarmlab.time());
  const most = tLost + s.speed * (Date.now() - restoredAt) / 1000 + 0.01;
  check(`${label}: restored: the run goes on from where it stopped`, t0 >= tLost && t0 <= most,
        `t ${tLost.toFixed(3)} at the loss, ${t0.toFixed(3)} ${((Date.now() - restoredAt) / 1000).toFixed(1)} s after the restore`);
  const runs = await clockAdvances(page);
  check(`${label}: restored: the clock advances`, runs.ok, runs.detail);
  const speed = await maxSpeed(page);
  check(`${label}: the student's max speed is still there`, speed === EDITED_SPEED, `max speed ${speed}`);
  check(`${label}: no error overlay after the restore`, !(await noticeNow(page)).overlay);
}

async function main(url) {
  mkdirSync(shotDir, { recursive: true });
  await launchBrowser({ width: SIZES[0][0], height: SIZES[0][1] });
  const { page, started, error } = await openApp(`${url}#preset=${base64url(Buffer.from(JSON.stringify(PRESET)))}`,
                                                  'context', `(${harness.recordLiveRegion})();`);
  if (!check('the app starts', started, error || '')) return;

  // The student's change, through the parallel DOM: the max speed typed into its field.
  const keys = person(page, 'keyboard');
  const mouse = person(page, 'mouse');
  await keys.type(FIELD, String(EDITED_SPEED));
  await page.waitForFunction((v) => JSON.parse(window.swarmlab.preset()).particles.velocity.speed === v, EDITED_SPEED,
                             { timeout: 20_000 }).catch(() => {});
  check('the student types a max speed into its field', await maxSpeed(page) === EDITED_SPEED,
        `max speed ${await maxSpeed(page)}`);
  if (!(await mouse.find('button', /Pause/).count())) await mouse.press('button', /Play/);
  const plays = await clockAdvances(page);
  check('the run plays', plays.ok, plays.detail);

  for (const [W, H] of SIZES) await lostAndRestored(page, W, H, 'dark');
  await page.setViewportSize({ width: SIZES[0][0], height: SIZES[0][1] });
  await laidOut(page, SIZES[0][0], SIZES[0][1]);
  await mouse.press('menuitem', 'View');
  await mouse.press('menuitem', 'Light theme');
  await page.waitForFunction(() => window.swarmlab.state().theme === 'light', null, { timeout: 20_000 }).catch(() => {});
  if (!check('View > Light theme', (await appState(page)).theme === 'light')) return;
  for (const [W, H] of SIZES) await lostAndRestored(page, W, H, 'light');

  await page.setViewportSize({ width: SIZES[0][0], height: SIZES[0][1] });
  await laidOut(page, SIZES[0][0], SIZES[0][1]);
  await keys.find('textbox', FIELD).waitFor({ state: 'attached', timeout: 20_000 }).catch(() => {});
  const field = await keys.find('textbox', FIELD).evaluate((e) => e.value).catch(() => null);
  check('after four losses the field still shows the student\'s max speed', Number(field) === EDITED_SPEED, `"${field}"`);
  const stray = consoleLog.filter((t) => COMPLAINT.test(t) && !INJECTED.test(t));
  check('no WebGL warning but the loss itself (no INVALID_OPERATION)', stray.length === 0,
        `${stray.length} lines: ${stray.slice(0, 3).join(' | ')}`);
  check('no page errors', pageErrors.length === 0, pageErrors.join(' | '));
  check('no console errors', consoleErrors.length === 0, consoleErrors.join(' | '));
}

runSuite('context_e2e', 280_000, main);
