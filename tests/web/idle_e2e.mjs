// A school day's battery and a slow device (issue 26): paused and still, the app draws only when
// something changes, its frame loop sleeps (asks the browser for no frame) and its main thread
// costs under 5 % of a core over 10 s (Chrome DevTools Protocol, Performance.getMetrics'
// ThreadTime; its TaskDuration reported); a person's press draws again at once; a
// hidden tab pauses its run and the page says so when the student comes back, unless View >
// Keep running in a hidden tab is on; with the CPU slowed 20 times (CDP), well under 10 frames
// a second, the run keeps its set speed or says that it cannot. A person acts through the
// parallel DOM (person.mjs); the hidden tab is injected (headless Chromium never hides a tab:
// the test sets document.visibilityState and sends visibilitychange, as the browser would).
// Figures are reported; every wait is on a condition, and the measuring windows are
// measurements.
import * as harness from './harness.mjs';
import { person } from './person.mjs';

const { check, base64url, shipped, openApp, launchBrowser, closeBrowser, runSuite, clockAdvances, clockStands,
        sleep, analysePng, outDir, pageErrors, consoleErrors } = harness;

const HIDDEN_NOTICE = 'Paused while this tab was hidden';

/** The main thread's busy share, the frames drawn and the frame loop's iterations over `ms` of
 *  the page's own time. */
async function measure(page, cdp, ms) {
  const metrics = () => harness.pageMetrics(cdp);
  const drawn = () => page.evaluate(() => [window.swarmlab.state().frames_drawn, window.swarmlab.frames()]);
  const a = await metrics(), [f1, i1] = await drawn();
  await sleep(ms);
  const b = await metrics(), [f2, i2] = await drawn();
  const seconds = b.Timestamp - a.Timestamp;
  // TaskDuration: the wall time of the main thread's tasks (what the issue reports), which a
  // loaded machine stretches by preempting them; ThreadTime: the main thread's CPU time, what a
  // battery pays.
  return { busy: (b.TaskDuration - a.TaskDuration) / seconds, cpu: (b.ThreadTime - a.ThreadTime) / seconds,
           fps: (f2 - f1) / seconds, frames: f2 - f1, iterations: i2 - i1, seconds };
}
const percent = (x) => `${(100 * x).toFixed(1)} %`;

/** Tells the page it was hidden or shown again, as the browser does when a tab goes behind. */
async function setHidden(page, hidden) {
  await page.evaluate((h) => {
    Object.defineProperty(document, 'visibilityState', { configurable: true, get: () => (h ? 'hidden' : 'visible') });
    Object.defineProperty(document, 'hidden', { configurable: true, get: () => h });
    document.dispatchEvent(new Event('visibilitychange'));
  }, hidden);
}

const stateOf = (page) => page.evaluate(() => window.swarmlab.state());
const until = (page, fn, arg, ms = 30_000) => page.waitForFunction(fn, arg, { timeout: ms }).then(() => true, () => false);

async function main(url) {
  // A light preset that runs long (35 time units): nothing ends while the checks play it.
  const light = base64url(Buffer.from(JSON.stringify(shipped('methods-vs-analytic.json'))));
  await launchBrowser({ width: 1366, height: 768 });
  const { page, started, error } = await openApp(`${url}#preset=${light}`, 'idle');
  if (!check('the app starts', started, error || '')) return;
  const me = person(page, 'mouse');
  const cdp = await page.context().newCDPSession(page);
  await cdp.send('Performance.enable');

  // 1. Playing: frames come, and what they cost (reported).
  if (!(await stateOf(page)).playing) await me.press('button', /Play/);
  const playing = await measure(page, cdp, 5000);
  check('playing, the app draws frames', playing.frames > 0,
        `${playing.fps.toFixed(1)} frames/s drawn, main thread ${percent(playing.cpu)} CPU, ${percent(playing.busy)} busy over ${playing.seconds.toFixed(1)} s`);

  // 2. Paused and still: no frame drawn, the main thread nearly free.
  await me.press('button', /Pause/);
  check('Pause pressed: the app goes idle and its frame loop sleeps',
        await until(page, () => { const s = window.swarmlab.state(); return !s.playing && s.idle && window.swarmlab.sleeping(); }));
  const beforeShot = await page.screenshot();
  const paused = await measure(page, cdp, 10_000);
  check('paused for 10 s, the main thread costs under 5 % of a core', paused.cpu < 0.05,
        `${percent(paused.cpu)} of a core (CPU time), ${percent(paused.busy)} busy (task time), ${paused.frames} frames drawn, ` +
        `${paused.iterations} loop iterations in ${paused.seconds.toFixed(1)} s (playing: ${percent(playing.cpu)} CPU, ${percent(playing.busy)} busy)`);
  check('paused and still, the loop asks for no frame and draws none',
        paused.frames === 0 && paused.iterations === 0, `${paused.frames} frames drawn, ${paused.iterations} loop iterations`);

  // 3. A person's press draws at once: the View menu opens and shows its new entry.
  await me.press('menuitem', 'View');
  const menuSeen = await me.find('menuitem', 'Keep running in a hidden tab').waitFor({ state: 'attached', timeout: 20_000 })
    .then(() => true, () => false);
  check('while idle, a press draws: the View menu opens with "Keep running in a hidden tab"', menuSeen);
  const menuShot = await page.screenshot({ path: `${outDir}/idle-menu-1366x768.png` });
  const [still, open] = await Promise.all([analysePng(beforeShot), analysePng(menuShot)]);
  check('the screenshot after the press is not the idle one', Buffer.compare(beforeShot, menuShot) !== 0,
        `${still.distinct} -> ${open.distinct} colours`);
  await page.keyboard.press('Escape');

  // 4. A hidden tab pauses its run and says so when the student is back; Play goes on.
  await me.press('button', /Play/);
  check('Play pressed: the run plays', await until(page, () => window.swarmlab.state().playing));
  await setHidden(page, true);
  check('hidden, the run pauses', await until(page, () => !window.swarmlab.state().playing));
  const standing = await clockStands(page);
  check('hidden, the clock stands', standing.ok, standing.detail);
  await setHidden(page, false);
  const told = await until(page, (text) => document.getElementById('notice-text').textContent.includes(text), HIDDEN_NOTICE);
  check('back in front, the page says the run was paused while hidden', told,
        await page.evaluate(() => document.getElementById('notice-text').textContent));
  const saidAloud = await until(page, () => /paus/i.test(document.getElementById('announcer').textContent));
  check('and the live region says it is paused', saidAloud, await page.evaluate(() => document.getElementById('announcer').textContent));
  await page.screenshot({ path: `${outDir}/idle-hidden-notice-1366x768.png` });
  await me.press('button', /Play/);
  const goesOn = await clockAdvances(page);
  check('Play goes on after the hidden pause', goesOn.ok, goesOn.detail);
  await page.getByRole('button', { name: 'Close' }).and(page.locator('#notice-close')).click();

  // 5. The teacher keeps it running: hidden, the run goes on, and nothing is said.
  await me.press('menuitem', 'View');
  await me.press('menuitem', 'Keep running in a hidden tab');
  check('View > Keep running in a hidden tab turns it on', await until(page, () => window.swarmlab.state().run_while_hidden));
  await setHidden(page, true);
  const runsOn = await clockAdvances(page);
  check('kept running, a hidden tab\'s run goes on', runsOn.ok && (await stateOf(page)).playing, runsOn.detail);
  await setHidden(page, false);
  const quiet = await page.evaluate(() => document.getElementById('notice').hidden);
  check('and nothing is said when it comes back', quiet);
  await closeBrowser();

  // 6. A slow device: the CPU slowed by CDP to well under 10 frames a second. The run keeps its
  // set speed (the simulated time over the page's own time, within 10 %), or says it cannot.
  await launchBrowser({ width: 390, height: 844, hasTouch: true, isMobile: true });
  const gas = base64url(Buffer.from(JSON.stringify(shipped('hot-wall.json'))));
  const slow = await openApp(`${url}#preset=${gas}`, 'idle-slow');
  if (!check('the app starts on a phone', slow.started, slow.error || '')) return;
  const slowCdp = await slow.page.context().newCDPSession(slow.page);
  const rate = 20;
  await slowCdp.send('Emulation.setCPUThrottlingRate', { rate });
  const sample = () => slow.page.evaluate(() => [window.swarmlab.time(), performance.now(), window.swarmlab.state().frames_drawn]);
  // The first slow seconds are the change itself: the measurement starts after two of them.
  const [, p0] = await sample();
  await until(slow.page, (p) => performance.now() > p + 2000, p0, 60_000);
  const [t1, p1, g1] = await sample();
  await until(slow.page, (p) => performance.now() > p + 6000, p1, 60_000);
  const [t2, p2, g2] = await sample();
  const s = await stateOf(slow.page);
  const fps = (g2 - g1) / ((p2 - p1) / 1000);
  const kept = (t2 - t1) / (s.speed * (p2 - p1) / 1000);
  const said = s.speed_ratio < 0.97;
  check(`CPU slowed ${rate}x (${fps.toFixed(1)} frames/s drawn): the run keeps its speed or says it cannot`,
        s.playing && (kept > 0.9 || said),
        `simulated ${(t2 - t1).toFixed(3)} in ${((p2 - p1) / 1000).toFixed(2)} s at speed ${s.speed.toFixed(3)}: ` +
        `${percent(kept)} of the set speed; the app says ${percent(s.speed_ratio)}`);
  // (The app's figure is over its last second, this one over six: at one or two frames a
  // second on a loaded machine they differ by 20 % and more, so only the claim is judged.)
  await slow.page.screenshot({ path: `${outDir}/idle-slow-390x844.png` });
  await slowCdp.send('Emulation.setCPUThrottlingRate', { rate: 1 });

  check('no page errors', pageErrors.length === 0, pageErrors.join(' | '));
  check('no console errors', consoleErrors.length === 0, consoleErrors.join(' | '));
}

runSuite('idle_e2e', 240_000, main);
