// A class finishes every lesson on any device (issue 21): from the first visit's welcome
// through every shipped lesson to its summary, on a phone (390x844 and 844x390) and a tablet
// (820x1180) by touch alone, and on a 1366x768 laptop by keyboard alone; the phone held
// sideways and the tablet in the light theme (chosen from the View menu), the others dark. Everything is found
// through the parallel DOM by role and name and pressed with real input (tests/web/person.mjs);
// window.swarmlab is only read. Each task is answered once wrongly, then rightly, with the
// right number from the physics (2 pi / sqrt(J M), sqrt(J M), sum of m, the energy of the
// preset's initial state) or, for P and T, as the read-outs show them. A screenshot per step
// goes to build/web-test/walkthrough/, with what the live region said (a screen reader's
// transcript, checked: the welcome, every step, the feedback, P and T as the read-outs show
// them). The last line is "N passed, M failed".
//   node tests/web/walkthrough_e2e.mjs [device...]   (devices: phone, phone-landscape, tablet, laptop)
import { readFileSync, readdirSync, mkdirSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import * as harness from './harness.mjs';
import { person } from './person.mjs';

const { root, outDir, check, openApp, launchBrowser, runSuite, closeBrowser, pageErrors } = harness;

const DEVICES = {
  phone: { width: 390, height: 844, touch: true },
  'phone-landscape': { width: 844, height: 390, touch: true, theme: 'light' },
  tablet: { width: 820, height: 1180, touch: true, theme: 'light' },
  laptop: { width: 1366, height: 768, touch: false },
};
const lessonDir = join(root, 'assets/lessons');
const lessons = readdirSync(lessonDir).filter((f) => f.endsWith('.json')).sort()
  .map((f) => JSON.parse(readFileSync(join(lessonDir, f), 'utf8')));

// The physics a student would use for the right number (independent of the app's code), from
// the preset's particles, or for a generated swarm of equal masses its count times its mass
// (docs/presets.md, "Preset reference"; default 1). Random masses would leave M to the read-outs.
function physics(preset, M) {
  const ps = Array.isArray(preset.particles) ? preset.particles : null;
  const J = preset.J;
  if (ps) M = ps.reduce((s, p) => s + p.m, 0);
  else if (typeof (preset.particles.mass ?? 1) === 'number') M = preset.particles.count * (preset.particles.mass ?? 1);
  let E = null;
  if (ps) {
    let KE = 0, PE = 0;
    ps.forEach((p) => { KE += 0.5 * p.m * p.v.reduce((s, v) => s + v * v, 0); });
    for (let i = 0; i < ps.length; ++i)
      for (let j = i + 1; j < ps.length; ++j) {
        const d2 = [0, 1, 2].reduce((s, k) => s + (ps[i].r[k] - ps[j].r[k]) ** 2, 0);
        PE += 0.5 * J * ps[i].m * ps[j].m * d2;  // F = -J m_i m_j r: U = J m_i m_j r^2 / 2
      }
    E = KE + PE;
  }
  return { M, J, omega: Math.sqrt(Math.abs(J * M)), period: 2 * Math.PI / Math.sqrt(J * M), E };
}

// A read-out as a screen reader reads it ("P = 43.56 ± 14"): its first number.
async function readout(me, symbol) {
  const row = me.dom.locator('p', { hasText: new RegExp(`^${symbol} = `) }).first();
  await row.waitFor({ state: 'attached', timeout: 20_000 });
  return parseFloat((await row.textContent()).slice(symbol.length + 3));
}

async function rightNumber(page, me, task) {
  const q = task.quantity;
  if (q === 'P' || q === 'T') return readout(me, q);  // as the read-outs show it
  const preset = await page.evaluate(() => JSON.parse(window.swarmlab.preset()));
  const generated = !Array.isArray(preset.particles) && typeof (preset.particles.mass ?? 1) !== 'number';
  const M = generated ? await readout(me, 'M') : undefined;
  const value = physics(preset, M)[q];
  return value ?? readout(me, q);
}

async function walk(url, name) {
  const device = DEVICES[name];
  await launchBrowser({ width: device.width, height: device.height, hasTouch: device.touch, isMobile: device.touch });
  const shots = join(outDir, 'walkthrough');
  mkdirSync(shots, { recursive: true });
  const { page, started, error } = await openApp(url + '?welcome', `walk-${name}`, listenToLiveRegion);
  if (!check(`${name}: the app starts`, started, error || '')) return;
  const me = person(page, device.touch ? 'touch' : 'keyboard');
  // Where the walk's time goes (the log says it at the end): presses, typing, screenshots.
  const spent = { press: { count: 0, ms: 0 }, type: { count: 0, ms: 0 } };
  for (const act of Object.keys(spent)) {
    const doIt = me[act];
    me[act] = async (...args) => {
      const start = Date.now();
      try { return await doIt(...args); } finally { spent[act].count += 1; spent[act].ms += Date.now() - start; }
    };
  }
  const walkStart = Date.now();
  const shots_taken = { count: 0, ms: 0 };
  const shot = async (file) => {
    const start = Date.now();
    await page.screenshot({ path: join(shots, `${name}-${file}.png`) });
    shots_taken.count += 1;
    shots_taken.ms += Date.now() - start;
  };
  const said = (text) => me.dom.getByText(text, { exact: false }).first().waitFor({ state: 'attached', timeout: 20_000 });

  await me.find('heading', 'Welcome to Swarm Lab').waitFor({ state: 'attached', timeout: 20_000 });
  if (device.theme === 'light') {
    // As a teacher at a bright projector would: View > Light theme.
    await me.press('menuitem', 'View');
    await me.press('menuitem', 'Light theme');
    await page.waitForFunction(() => window.swarmlab.state().theme === 'light', null, { timeout: 20_000 });
  }
  await shot('00-welcome');
  const domText = [];  // lesson 1 as the parallel DOM reads it, step by step
  let summaries = 0;
  await me.press('button', `Start: ${lessons[0].title}`);
  for (const [l, lesson] of lessons.entries()) {
    await said(lesson.title);
    for (const [i, step] of lesson.steps.entries()) {
      await said(`Step ${i + 1} of ${lesson.steps.length}`);
      await shot(`L${l + 1}-s${i + 1}`);
      const task = step.task;
      if (task) await answer(page, me, task, `${name} L${l + 1} s${i + 1}`, lesson);
      if (l === 0) domText.push(`-- step ${i + 1}`, ...(await lessonText(me)));
      await me.press('button', i + 1 < lesson.steps.length ? /^Next \u2192/ : 'Finish');
    }
    await said('Summary');
    summaries += 1;
    await shot(`L${l + 1}-summary`);
    if (l + 1 < lessons.length) await me.press('button', `Next lesson: ${lessons[l + 1].title}`);
  }
  check(`${name}: every lesson walked to its summary`, summaries === lessons.length,
        `${summaries} of ${lessons.length}; of ${((Date.now() - walkStart) / 1000).toFixed(0)} s, ` +
        `${spent.press.count} presses took ${(spent.press.ms / 1000).toFixed(1)} s, ` +
        `${spent.type.count} typed answers ${(spent.type.ms / 1000).toFixed(1)} s, ` +
        `${shots_taken.count} screenshots ${(shots_taken.ms / 1000).toFixed(1)} s`);
  await checkTranscript(page, name);
  checkLessonText(domText, name);
}

// The headings and paragraphs of the region that holds the lesson, in reading order.
function lessonText(me) {
  return me.dom.locator('p', { hasText: /^Step \d+ of \d+$/ }).first().evaluate((step) =>
    [...step.closest('.pdom-region').querySelectorAll('h2, p')].map((e) => e.textContent));
}

// Lesson 1 read through the parallel DOM: each step's text, its question and the feedback on
// the answer given, with the device's words and without emphasis marks.
function checkLessonText(domText, name) {
  writeFileSync(join(outDir, 'walkthrough', `${name}-lesson1-dom.txt`), domText.join('\n') + '\n');
  const plain = (t) => t.replace(/\*/g, '').split(/[{\n]/)[0].slice(0, 30);
  const missing = [];
  lessons[0].steps.forEach((step, i) => {
    const at = domText.indexOf(`-- step ${i + 1}`);
    const end = domText.indexOf(`-- step ${i + 2}`);
    const lines = domText.slice(at, end < 0 ? undefined : end).join('\n');
    if (!lines.includes(plain(step.text))) missing.push(`step ${i + 1} text`);
    if (step.task && !lines.includes(plain(step.task.prompt))) missing.push(`step ${i + 1} question`);
    if (step.task?.kind === 'measure' && !/Right: /.test(lines)) missing.push(`step ${i + 1} feedback`);
    if (step.task?.kind === 'predict' && !lines.includes('Your prediction:')) missing.push(`step ${i + 1} prediction`);
  });
  check(`${name}: lesson 1 reads in the parallel DOM with every step, question and feedback`,
        missing.length === 0, missing.join(', '));
}

// Every text the live region (#announcer) takes, in order, as a screen reader hears it.
function listenToLiveRegion() {
  window.liveRegionSaid = [];
  new MutationObserver((_, waiting) => {
    const region = document.getElementById('announcer');
    if (!region) return;
    const listen = new MutationObserver(() => window.liveRegionSaid.push(region.textContent.trim()));
    listen.observe(region, { childList: true, characterData: true, subtree: true });
    waiting.disconnect();
  }).observe(document, { childList: true, subtree: true });
}

const liveRegionSaid = (page) => page.evaluate(() => window.liveRegionSaid);

async function checkTranscript(page, name) {
  const said = await liveRegionSaid(page);
  writeFileSync(join(outDir, 'walkthrough', `${name}-transcript.txt`), said.join('\n') + '\n');
  const heard = (text) => said.some((s) => s.includes(text));
  check(`${name}: the live region read the welcome`, heard('Welcome to Swarm Lab. Lessons:'));
  const missed = [];
  for (const lesson of lessons)
    lesson.steps.forEach((_, i) => {
      const place = `${lesson.title}, step ${i + 1} of ${lesson.steps.length}.`;
      if (!heard(place)) missed.push(place);
    });
  check(`${name}: the live region read every step`, missed.length === 0, missed.slice(0, 3).join(' | '));
  check(`${name}: the live region read feedback, right and wrong`, heard('Right: ') && heard('Not yet: '));
  check(`${name}: the live region read every summary`,
        lessons.every((l) => heard(`${l.title}: summary. Finished: `)));
}

async function answer(page, me, task, where, lesson) {
  const letter = (i) => String.fromCharCode(65 + i);
  if (task.kind === 'predict') {
    const region = await keyboardRegion(me, new RegExp(`^Predict ${letter(0)}: `));
    await me.press('button', new RegExp(`^Predict ${letter(0)}: `));
    check(`${where}: a prediction is recorded and compared`, await feedbackSays(me, 'Your prediction:'));
    await focusStays(page, me, region, where);
    return;
  }
  if (task.kind === 'choice') {
    const wrong = task.answer === 0 ? 1 : 0;
    const region = await keyboardRegion(me, new RegExp(`^Pick ${letter(wrong)}: `));
    await me.press('button', new RegExp(`^Pick ${letter(wrong)}: `));
    check(`${where}: a wrong choice is marked wrong`, await feedbackSays(me, task.feedback ? task.feedback[wrong] : 'Not'));
    await focusStays(page, me, region, where);
    await me.press('button', new RegExp(`^Pick ${letter(task.answer)}: `));
    check(`${where}: the right choice is marked right`, await feedbackSays(me, task.feedback ? task.feedback[task.answer] : 'Right'));
    return;
  }
  if (task.quantity === 'P' || task.quantity === 'T') {
    // As the step says: a running average over the task's window, read with the run paused (it
    // would drift while the number is typed).
    await openTab(me, 'Plots');
    await me.type('average over', String(task.window ?? 0.5));
    await openTab(me, 'Read-outs');
    // Paused on the step before: play until the read-outs show P and T (the wall's first
    // samples), as the step asks to watch them change.
    if (!(await me.find('button', /Pause/).count())) await me.press('button', /Play/);
    for (const symbol of ['P', 'T'])
      await me.dom.locator('p', { hasText: new RegExp(`^${symbol} = [-+]?[0-9]`) }).first()
        .waitFor({ state: 'attached', timeout: 60_000 });
    await pauseAndListen(page, me, where);
  }
  await openTab(me, 'Read-outs');
  const right = await rightNumber(page, me, task);
  await openTab(me, 'Lesson');

  await me.type('Your answer', String(Number((3 * right + 1).toPrecision(4))));
  check(`${where}: a wrong number is marked wrong`, await feedbackSays(me, /^Not yet: /));
  await me.type('Your answer', String(Number(right.toPrecision(5))));
  check(`${where}: the right number is marked right (${right.toPrecision(5)})`, await feedbackSays(me, /^Right: /));
}

// For a keyboard user, the panel a button is in (its region of the parallel DOM).
const keyboardRegion = (me, name) => me.way !== 'keyboard' ? null
  : me.find('button', name).evaluate((e) => e.closest('.pdom-region').getAttribute('aria-label'));

// A keyboard user's choice gives way to its feedback: the focus goes on to the lesson's next
// item, where Tab goes on from, not to another panel (found 40 Tabs away before 2026-11-27).
async function focusStays(page, me, region, where) {
  if (me.way !== 'keyboard') return;
  const inRegion = await page.waitForFunction((r) => document.activeElement?.closest('.pdom-region')?.getAttribute('aria-label') === r,
                                              region, { timeout: 10_000 }).then(() => true, () => false);
  const at = await page.evaluate(() => { const e = document.activeElement; return e && (e.getAttribute('aria-label') || e.textContent || e.id); });
  check(`${where}: after the choice the focus stays in ${region}`, inRegion, `on ${at}`);
}

// On a phone or tablet the panels are tabs of a drawer below the view: the person opens the
// one that holds what the step asks for. A wide layout shows them all and has no such tab.
async function openTab(me, name) {
  const tab = me.find('tab', name);
  if (!(await tab.count()) || (await tab.getAttribute('aria-selected')) === 'true') return;
  await me.press('tab', name);
  await me.dom.locator('[role=tab][aria-selected=true]', { hasText: name }).first()
    .waitFor({ state: 'attached', timeout: 15_000 })
    .catch(async () => { throw new Error(`the tab ${name} did not open (${await tabStates(me)})`); });
}
const tabStates = (me) => me.dom.locator('[role=tab]').evaluateAll(
  (tabs) => tabs.map((t) => `${t.getAttribute('aria-label') || t.textContent}:${t.getAttribute('aria-selected')}`).join(' '));

// Pauses: the live region then says P and T as the read-outs show them. Lesson 5's run loops:
// a pause that lands as it starts again, before the wall's first sample, is rightly said
// without P (the read-outs wait for samples too); the person plays on and pauses again.
async function pauseAndListen(page, me, where) {
  let said = '';
  for (let tries = 0; tries < 3; ++tries) {
    const before = (await liveRegionSaid(page)).length;
    await me.press('button', /Pause/);
    // What the live region says from "Paused, " on (a lesson's own words may come before it
    // and may hold a "P = " of their own).
    const text = await page.waitForFunction(
      (n) => window.liveRegionSaid.slice(n).map((s) => s.slice(s.indexOf('Paused, ')))
        .filter((s) => s.startsWith('Paused, ')).pop(), before, { timeout: 20_000 })
      .then((h) => h.jsonValue(), async () => {
        const heard = (await liveRegionSaid(page)).slice(before).slice(-4).join(' | ') || 'nothing';
        const focus = await page.evaluate(() => document.activeElement?.getAttribute('aria-label') || document.activeElement?.tagName);
        throw new Error(`no "Paused" from the live region within 20 s of pressing Pause (it said: ${heard}; focus on ${focus})`);
      });
    said = text;
    if (/ P = /.test(text)) {
      const number = (symbol) => parseFloat(text.split(` ${symbol} = `)[1]);
      for (const symbol of ['P', 'T']) {
        const shown = await readout(me, symbol);
        check(`${where}: the live region says ${symbol} as the read-out shows it (${number(symbol)}, ${shown})`,
              Math.abs(number(symbol) - shown) <= 1e-3 * Math.abs(shown));
      }
      return;
    }
    // No P said: the read-out must be waiting for its samples too.
    const waiting = await me.dom.locator('p', { hasText: /^P = [^-+0-9]/ }).first()
      .waitFor({ state: 'attached', timeout: 10_000 }).then(() => true, () => false);
    if (!waiting) throw new Error(`the live region said no P ("${text}") while the read-out shows one`);
    await me.press('button', /Play/);
    for (const symbol of ['P', 'T'])
      await me.dom.locator('p', { hasText: new RegExp(`^${symbol} = [-+]?[0-9]`) }).first()
        .waitFor({ state: 'attached', timeout: 60_000 });
  }
  throw new Error(`three pauses in a row came before the wall's first sample (the last said "${said}")`);
}

// Waits until a paragraph of the parallel DOM says it (feedback appears next to Check).
async function feedbackSays(me, text) {
  const plain = (t) => t.replace(/\*/g, '').split('{')[0].slice(0, 40);
  const pattern = text instanceof RegExp ? text : new RegExp(plain(text).replace(/[.*+?^${}()|[\]\\]/g, '\\$&'));
  try { await me.dom.locator('p', { hasText: pattern }).first().waitFor({ state: 'attached', timeout: 15_000 }); return true; }
  catch { return false; }
}

const wanted = process.argv.slice(2).length ? process.argv.slice(2) : Object.keys(DEVICES);
// One device per process lets ctest walk two at once (tests/CMakeLists.txt); each keeps its own log.
const suiteName = process.argv.slice(2).length ? `walkthrough-${wanted.join('-')}` : 'walkthrough';
await runSuite(suiteName, 1_750_000, async (url) => {
  for (const name of wanted) {
    try { await walk(url, name); }
    catch (e) {
      check(`${name} walkthrough`, false, String(e && e.stack || e).split('\n').slice(0, 3).join(' / '));
      await harness.context?.pages().at(-1)?.screenshot({ path: join(outDir, 'walkthrough', `${name}-failed.png`) }).catch(() => {});
    }
    await closeBrowser();
  }
  check('no page errors', pageErrors.length === 0, pageErrors.join(' | '));
});
