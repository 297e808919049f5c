// A class finishes every lesson on any device (issue 21): from the first visit's welcome
// through every shipped lesson to its summary, on a phone (390x844 and 844x390) and a tablet
// (820x1180) by touch alone, and on a 1366x768 laptop by keyboard alone. Everything is found
// through the parallel DOM by role and name and pressed with real input (tests/web/person.mjs);
// window.swarmlab is only read. Each task is answered once wrongly, then rightly, with the
// right number from the physics (2 pi / sqrt(J M), sqrt(J M), sum of m, the energy of the
// preset's initial state) or, for P and T, as the read-outs show them. A screenshot per step
// goes to build/web-test/walkthrough/. The last line is "N passed, M failed".
//   node tests/web/walkthrough_e2e.mjs [device...]   (devices: phone, phone-landscape, tablet, laptop)
import { readFileSync, readdirSync, mkdirSync } from 'node:fs';
import { join } from 'node:path';
import * as harness from './harness.mjs';
import { person } from './person.mjs';

const { root, outDir, check, openApp, launchBrowser, runSuite, closeBrowser, pageErrors } = harness;

const DEVICES = {
  phone: { width: 390, height: 844, touch: true },
  'phone-landscape': { width: 844, height: 390, touch: true },
  tablet: { width: 820, height: 1180, touch: true },
  laptop: { width: 1366, height: 768, touch: false },
};
const lessonDir = join(root, 'assets/lessons');
const lessons = readdirSync(lessonDir).filter((f) => f.endsWith('.json')).sort()
  .map((f) => JSON.parse(readFileSync(join(lessonDir, f), 'utf8')));

// The physics a student would use for the right number (independent of the app's code).
function physics(preset) {
  const ps = preset.particles || [];
  const M = ps.reduce((s, p) => s + p.m, 0);
  const J = preset.J;
  let KE = 0, PE = 0;
  ps.forEach((p) => { KE += 0.5 * p.m * p.v.reduce((s, v) => s + v * v, 0); });
  for (let i = 0; i < ps.length; ++i)
    for (let j = i + 1; j < ps.length; ++j) {
      const d2 = [0, 1, 2].reduce((s, k) => s + (ps[i].r[k] - ps[j].r[k]) ** 2, 0);
      PE += 0.5 * J * ps[i].m * ps[j].m * d2;  // F = -J m_i m_j r: U = J m_i m_j r^2 / 2
    }
  return { M, J, omega: Math.sqrt(Math.abs(J * M)), period: 2 * Math.PI / Math.sqrt(J * M), E: KE + PE };
}

async function rightNumber(page, task) {
  const app = await page.evaluate(() => ({ s: window.swarmlab.state(), preset: JSON.parse(window.swarmlab.preset()) }));
  const q = task.quantity;
  if (q === 'P' || q === 'T') return app.s[q];  // as the read-outs show it
  return physics(app.preset)[q];
}

async function walk(url, name) {
  const device = DEVICES[name];
  await launchBrowser({ width: device.width, height: device.height, hasTouch: device.touch, isMobile: device.touch });
  const shots = join(outDir, 'walkthrough');
  mkdirSync(shots, { recursive: true });
  const { page, started, error } = await openApp(url + '?welcome', `walk-${name}`);
  if (!check(`${name}: the app starts`, started, error || '')) return;
  const me = person(page, device.touch ? 'touch' : 'keyboard');
  const shot = (file) => page.screenshot({ path: join(shots, `${name}-${file}.png`) });
  const said = (text) => me.dom.getByText(text, { exact: false }).first().waitFor({ state: 'attached', timeout: 20_000 });

  await me.find('heading', /Welcome/).waitFor({ state: 'attached', timeout: 20_000 });
  await shot('00-welcome');
  await me.press('button', `Start: ${lessons[0].title}`);
  for (const [l, lesson] of lessons.entries()) {
    await said(lesson.title);
    for (const [i, step] of lesson.steps.entries()) {
      await said(`Step ${i + 1} of ${lesson.steps.length}`);
      await shot(`L${l + 1}-s${i + 1}`);
      const task = step.task;
      if (task) await answer(page, me, task, `${name} L${l + 1} s${i + 1}`);
      await me.press('button', i + 1 < lesson.steps.length ? 'Next' : 'Finish');
    }
    await said('Summary');
    await shot(`L${l + 1}-summary`);
    if (l + 1 < lessons.length) await me.press('button', `Next lesson: ${lessons[l + 1].title}`);
  }
  check(`${name}: every lesson walked to its summary`, true);
}

async function answer(page, me, task, where) {
  if (task.kind === 'predict') {
    await me.press('radio', task.options[0]);
    await me.press('button', 'Predict');
    check(`${where}: a prediction is answered with the outcome`, await feedbackSays(me, task.outcome.slice(0, 30)));
    return;
  }
  if (task.kind === 'choice') {
    const wrong = task.answer === 0 ? 1 : 0;
    await me.press('radio', task.options[wrong]);
    await me.press('button', 'Check');
    check(`${where}: a wrong choice is marked wrong`, await feedbackSays(me, 'Not'));
    await me.press('radio', task.options[task.answer]);
    await me.press('button', 'Check');
    check(`${where}: the right choice is marked right`, await feedbackSays(me, 'Right'));
    return;
  }
  const right = await rightNumber(page, task);
  await me.type(task.prompt, String(-3 * right || 1));
  check(`${where}: a wrong number is marked wrong`, await feedbackSays(me, 'Not'));
  await me.type(task.prompt, right.toPrecision(4));
  check(`${where}: the right number is marked right (${right.toPrecision(4)})`, await feedbackSays(me, 'Right'));
}

async function feedbackSays(me, text) {
  try { await me.find('paragraph', new RegExp(text.replace(/[.*+?^${}()|[\]\\]/g, '\\$&'))).waitFor({ state: 'attached', timeout: 15_000 }); return true; }
  catch { return false; }
}

const wanted = process.argv.slice(2).length ? process.argv.slice(2) : Object.keys(DEVICES);
await runSuite('walkthrough', 1_200_000, async (url) => {
  for (const name of wanted) {
    try { await walk(url, name); }
    catch (e) { check(`${name} walkthrough`, false, String(e && e.stack || e).split('\n').slice(0, 3).join(' / ')); }
    await closeBrowser();
  }
  check('no page errors', pageErrors.length === 0, pageErrors.join(' | '));
});
