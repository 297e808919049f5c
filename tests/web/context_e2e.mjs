// A lost WebGL context is survived (issue 26). Phones, tablets and Chromebooks drop the GPU
// context when the GPU resets, memory runs short or a tab stays long in the background. Here a
// student changes a mass through the parallel DOM (typed into its field with the keyboard) and
// plays the run; then the fault is injected (WEBGL_lose_context.loseContext(), the one call
// into the page that a person does not make): the message line says so in one calm line, the
// fatal overlay stays away, and the run waits where it was; then restoreContext(): the line
// goes, the live region says the picture is back, the canvas draws the particles again, the
// clock goes on from where it stopped, and the student's mass is still there. Four times on one
// page: at a laptop's 1366x768 and a phone's 390x844, in the dark theme and then in the light
// one (View > Light theme, as a person sets it). No page error, no console error, and no WebGL
// warning (an INVALID_OPERATION is one) but the single line loseContext() itself writes.
// Screenshots before the loss, during it and after the restore: build/web-test/context/.
// window.swarmlab is only read. Run through tests/web/run.sh; the last line is "N passed, M failed".
import { mkdirSync } from 'node:fs';
import { join } from 'node:path';
import * as harness from './harness.mjs';
import { person } from './person.mjs';

const { check, openApp, launchBrowser, runSuite, outDir, pageErrors, consoleErrors, analysePng, clockAdvances,
        shipped, base64url } = harness;

const shotDir = join(outDir, 'context');
const LOST = 'The picture is paused while the browser restarts its graphics. Your run and your changes are kept.';
const BACK = 'The picture is back.';
const SIZES = [[1366, 768], [390, 844]];
const EDITED_MASS = 2.5;  // particle 1's mass as the student types it (the preset's is 0.25)
// The four masses of Fig. 1, for long enough that the run never ends while the suite looks.
const PRESET = { ...shipped('fig1-four-masses.json'), duration: 100000 };
// The line loseContext() writes itself (the fault being injected); any other WebGL line fails.
const INJECTED = /^WebGL: CONTEXT_LOST_WEBGL: loseContext: context lost$/;

const appState = (page) => page.evaluate(() => window.swarmlab.state());
const firstMass = (page) => page.evaluate(() => JSON.parse(window.swarmlab.preset()).particles[0].m);
const noticeNow = (page) => page.evaluate(() => {
  const n = document.getElementById('notice');
  return { shown: !n.hidden, text: document.getElementById('notice-text').textContent, kind: n.className,
           live: n.getAttribute('aria-live'),
           overlay: !document.getElementById('overlay').classList.contains('hidden'),
           error: window.swarmlabError || null };
});

// In the page before its scripts: every text the live region takes (the app's too: while the
// run plays it says the time every few seconds).
function listen() {
  window.liveRegionSaid = [];
  new MutationObserver((_, waiting) => {
    const region = document.getElementById('announcer');
    if (!region) return;
    new MutationObserver(() => window.liveRegionSaid.push(region.textContent.trim()))
      .observe(region, { childList: true, characterData: true, subtree: true });
    waiting.disconnect();
  }).observe(document, { childList: true, subtree: true });
}

// The 3D view's rectangle, as analysePng measures it (x0, y0, x1, y1 in CSS pixels).
const viewRect = (s) => ({ view: [Math.round(s.view.x), Math.round(s.view.y),
                                  Math.round(s.view.x + s.view.width), Math.round(s.view.y + s.view.height)] });
// Drawn: not black, and the particles' colours in the view.
const drawn = (img) => img.blackShare < 0.5 && img.vivid.view >= 40;

async function shoot(page, file, rects, until = null) {
  const deadline = Date.now() + 20_000;
  let png, img;
  do {
    png = await page.screenshot({ path: join(shotDir, file) });
    img = await analysePng(png, rects);
  } while (until && !until(img) && Date.now() < deadline);
  console.log(`      ${file}: ${img.distinct} colours, black ${(100 * img.blackShare).toFixed(1)}%, ` +
              `most common ${img.topColor}, vivid pixels in the view ${img.vivid.view} -> build/web-test/context/${file}`);
  return img;
}

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
  const after = await shoot(page, `context-${name}-3-restored.png`, rects, drawn);
  check(`${label}: restored: the canvas draws the particles again`, drawn(after),
        `vivid ${after.vivid.view}, black ${(100 * after.blackShare).toFixed(1)}% (lost: vivid ${during.vivid.view})`);
  // From where it stopped: neither started again nor moved on while away (at most the run's
  // speed times the wall time since the restore).
  const t0 = await page.evaluate(() => window.swarmlab.time());
  const most = tLost + s.speed * (Date.now() - restoredAt) / 1000 + 0.01;
  check(`${label}: restored: the run goes on from where it stopped`, t0 >= tLost && t0 <= most,
        `t ${tLost.toFixed(3)} at the loss, ${t0.toFixed(3)} ${((Date.now() - restoredAt) / 1000).toFixed(1)} s after the restore`);
  const runs = await clockAdvances(page);
  check(`${label}: restored: the clock advances`, runs.ok, runs.detail);
  const mass = await firstMass(page);
  check(`${label}: the student's mass is still there`, mass === EDITED_MASS, `m1 = ${mass}`);
  check(`${label}: no error overlay after the restore`, !(await noticeNow(page)).overlay);
}

async function main(url) {
  mkdirSync(shotDir, { recursive: true });
  await launchBrowser({ width: SIZES[0][0], height: SIZES[0][1] });
  const webgl = [];
  const { page, started, error } = await openApp(`${url}#preset=${base64url(Buffer.from(JSON.stringify(PRESET)))}`,
                                                  'context', listen);
  if (!check('the app starts', started, error || '')) return;
  page.on('console', (m) => { if (/WebGL|GL_INVALID|INVALID_/.test(m.text())) webgl.push(m.text()); });

  // The student's change, through the parallel DOM: particle 1's mass typed into its field.
  const keys = person(page, 'keyboard');
  const mouse = person(page, 'mouse');
  await keys.type('m of particle 1', String(EDITED_MASS));
  await page.waitForFunction((m) => JSON.parse(window.swarmlab.preset()).particles[0].m === m, EDITED_MASS,
                             { timeout: 20_000 }).catch(() => {});
  check('the student types a mass into its field', await firstMass(page) === EDITED_MASS, `m1 = ${await firstMass(page)}`);
  await mouse.press('button', /Play/);
  const plays = await clockAdvances(page);
  check('Play: the run plays', plays.ok, plays.detail);

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
  await keys.find('textbox', 'm of particle 1').waitFor({ state: 'attached', timeout: 20_000 }).catch(() => {});
  const field = await keys.find('textbox', 'm of particle 1').evaluate((e) => e.value).catch(() => null);
  check('after four losses the mass field still shows the student\'s mass', Number(field) === EDITED_MASS, `"${field}"`);
  const stray = webgl.filter((t) => !INJECTED.test(t));
  check('no WebGL warning but the loss itself (no INVALID_OPERATION)', stray.length === 0,
        `${stray.length} lines: ${stray.slice(0, 3).join(' | ')}`);
  check('no page errors', pageErrors.length === 0, pageErrors.join(' | '));
  check('no console errors', consoleErrors.length === 0, consoleErrors.join(' | '));
}

runSuite('context_e2e', 280_000, main);
