// Lessons in the browser (docs/lessons.md, web/README.md): the welcome appears on the first
// visit and not on the second; every shipped lesson is walked to its end through the JS API,
// each measure task answered with the value the app's instruments read (lessonState().task
// .reading), each choice with its right option (read from the lesson file), each prediction
// recorded; a wrong answer is marked wrong; a broken lesson (bad JSON, a rule broken, an
// unknown id, a #lesson= link) gives a field-named message and the running lesson stays; a
// #lesson= link opens its lesson; a shipped lesson's id link opens it and anything else is
// refused in one sentence; Copy link during a lesson links the lesson; lesson 1 hides the
// read-outs until its timing is answered; runs go on (until, loop) while a step is read; Enter
// and keypad Enter in the answer field check it (real keys); Finish shows the summary.
// Screenshots of the welcome, the lesson panel and the summary at 390x844, 820x1180, 1366x768
// in both themes and presentation mode at 1920x1080 go to build/web-test/.
import { readFileSync, readdirSync } from 'node:fs';
import { join } from 'node:path';
import * as harness from './harness.mjs';
import { person } from './person.mjs';

const { root, check, base64url, openApp, screenshot, clockAdvances, launchBrowser, runSuite, pageErrors,
        consoleErrors } = harness;

const lessonDir = join(root, 'assets/lessons');
const lessonFiles = readdirSync(lessonDir).filter((f) => f.endsWith('.json')).sort();
const lessonById = Object.fromEntries(lessonFiles.map((f) => {
  const l = JSON.parse(readFileSync(join(lessonDir, f), 'utf8'));
  return [l.id, l];
}));

const api = (page, fn, ...args) => page.evaluate(({ fn, args }) => window.swarmlab[fn](...args), { fn, args });
// Waits until fn(arg) holds in the page (what an action should produce), or timeoutMs pass;
// returns whether it held.
const until = (page, fn, arg = null, timeoutMs = 20_000) =>
  page.waitForFunction(fn, arg, { timeout: timeoutMs }).then(() => true, () => false);
// Resizes the page and waits until the app has laid the canvas out at that size and the layout
// holds (state().display, layout_settled).
async function resize(page, width, height) {
  await page.setViewportSize({ width, height });
  return until(page, ([w, h]) => {
    const s = window.swarmlab.state();
    return s.display.width === w && s.display.height === h && s.layout_settled;
  }, [width, height]);
}
// Until the app has drawn `text` (the parallel DOM mirrors what the last frame drew).
const drawn = (page, text) => until(page, (t) => (document.getElementById('parallel-dom') || {}).textContent?.includes(t), text);

// Waits until the measure task's instruments read a value (P and T wait for wall hits), polling
// the page's own state; gives up only after READING_WAIT_MS (far beyond any loaded machine's
// first wall sample, inside the suite's watchdog) and then returns null, never a stale value.
const READING_WAIT_MS = 200_000;
async function readingShown(page) {
  const shown = await until(page, () => window.swarmlab.lessonState().task.reading !== null, null, READING_WAIT_MS);
  return shown ? page.evaluate(() => window.swarmlab.lessonState().task.reading) : null;
}

// Answers the open step's task the way a student who measured well would; returns the marking.
async function answerWell(page, lesson, st) {
  const task = st.task;
  if (task.kind === 'measure') {
    // P and T need wall hits first: a student waits until the instruments read a value, however
    // long a loaded machine takes (the suite's watchdog bounds a stall), and never answers before.
    const reading = await readingShown(page);
    if (reading === null) return { reading, marking: { correct: 'not answered: no reading was shown' } };
    // Read and answer in one evaluation, so no frame passes between them.
    return page.evaluate(() => {
      const reading = window.swarmlab.lessonState().task.reading;
      return { reading, marking: window.swarmlab.lessonAnswer(reading) };
    });
  }
  if (task.kind === 'choice') return { marking: await api(page, 'lessonAnswer', lesson.steps[st.step].task.answer) };
  return { marking: await api(page, 'lessonAnswer', 0) };
}

async function main(url) {
  await launchBrowser({ width: 1280, height: 720 });
  const first = await openApp(url + '?welcome', 'first-visit');
  if (!check('the app starts', first.started, first.error || '')) return;
  const page = first.page;

  // 1. The welcome: on the first visit, once.
  check('the welcome shows on the first visit', await api(page, 'welcomeShown'));
  await resize(page, 1280, 720);
  await screenshot(page, 'lessons-welcome-1280x720.png');
  await resize(page, 390, 844);
  await screenshot(page, 'lessons-welcome-390x844.png');
  await resize(page, 1280, 720);

  // 2. The shipped lessons. A lesson whose presets are not shipped yet is left out of the list
  // (as a broken preset is); the suite says which.
  const listed = await api(page, 'lessons');
  const listedIds = listed.map((l) => l.id);
  check('at least six shipped lessons are listed', listed.length >= 6, listedIds.join(', '));
  for (const id of Object.keys(lessonById).filter((id) => !listedIds.includes(id)))
    console.log(`      not listed (its presets are not shipped yet?): ${id}`);
  check('every listed lesson has a title and steps', listed.every((l) => l.title && l.steps > 0));

  // 3. Walk every listed lesson to its end.
  let wrongChecked = false, screenshotTaken = false;
  for (const { id } of listed) {
    const lesson = lessonById[id];
    check(`${id}: opens`, await api(page, 'openLesson', id));
    let st = await api(page, 'lessonState');
    check(`${id}: opens at its first step`, st && st.id === id && st.step === 0 && st.steps === lesson.steps.length,
          JSON.stringify(st && { id: st.id, step: st.step, steps: st.steps }));
    const problems = [];
    for (;;) {
      if (typeof lesson.steps[st.step].preset === 'string') {
        const name = JSON.parse(readFileSync(join(root, 'assets/presets', lesson.steps[st.step].preset), 'utf8')).name;
        const running = (await api(page, 'state')).name;
        if (running !== name) problems.push(`step ${st.step}: runs "${running}", not "${name}"`);
      }
      if (st.task) {
        if (!wrongChecked && st.task.kind === 'measure' && await readingShown(page) !== null) {
          const wrong = await page.evaluate(() => {
            const reading = window.swarmlab.lessonState().task.reading;
            return reading === null ? null : window.swarmlab.lessonAnswer(reading * 1.5);
          });
          if (wrong) {
            wrongChecked = true;
            check('a measurement 50% off is marked wrong', wrong.correct === false, JSON.stringify(wrong));
          }
        }
        if (!screenshotTaken && id === 'one-period' && st.task.kind === 'measure') {
          await drawn(page, `Step ${st.step + 1} of ${st.steps}`);
          await screenshot(page, 'lessons-panel-1280x720.png');
          await resize(page, 390, 844);
          await screenshot(page, 'lessons-panel-390x844.png');
          await resize(page, 1280, 720);
          screenshotTaken = true;
        }
        const { reading, marking } = await answerWell(page, lesson, st);
        const expected = st.task.kind === 'predict' ? null : true;
        if (marking.correct !== expected)
          problems.push(`step ${st.step} (${st.task.kind}${reading !== undefined ? ' ' + st.task.quantity + ' = ' + reading : ''}): ${JSON.stringify(marking)}`);
        if (st.task.kind === 'predict' && (await api(page, 'lessonState')).task.prediction !== 0)
          problems.push(`step ${st.step}: the prediction was not recorded`);
      }
      if (st.step + 1 >= st.steps) break;
      const next = await api(page, 'lessonNext');
      if (next.step !== st.step + 1) { problems.push(`next from ${st.step} gave ${next.step}`); break; }
      st = next;
    }
    check(`${id}: walked to its end, every task answered as the app measures`, problems.length === 0 && st.step === st.steps - 1,
          problems.join('; '));
  }
  check('a wrong answer was tried', wrongChecked);

  // Back moves a step back and sets its scene.
  await api(page, 'openLesson', 'one-period');
  const back = await api(page, 'lessonBack');
  check('lessonBack moves one step back', back.step === lessonById['one-period'].steps.length - 2, String(back.step));

  // 4. Broken lessons: a field-named message, and the running lesson stays.
  const before = await api(page, 'lessonState');
  const refusals = await page.evaluate(() => {
    const tries = ['{"lesson": 1, "id": "x"}', '{"lesson": 1,', 'no-such-lesson',
      { lesson: 1, id: 'x', title: 'X', summary: 'S', steps: [{ text: 'a', preset: 'two-body-circular.json',
        task: { kind: 'measure', prompt: 'p', quantity: 'period', tolerance: 0 } }] }];
    return tries.map((t) => { try { window.swarmlab.openLesson(t); return 'opened'; } catch (e) { return e.message; } });
  });
  check('a lesson without a title is refused by field', refusals[0] === 'swarmlab.openLesson(): title: missing (the lesson\'s title)', refusals[0]);
  check('lesson text that is not JSON is refused', refusals[1].startsWith('swarmlab.openLesson(): lesson: not valid JSON'), refusals[1]);
  check('an unknown lesson id is refused', refusals[2] === 'swarmlab.openLesson(): no shipped lesson "no-such-lesson"', refusals[2]);
  check('a broken rule is refused with its field', refusals[3] === 'swarmlab.openLesson(): steps[0].task.tolerance: must be > 0', refusals[3]);
  const after = await api(page, 'lessonState');
  check('after refusals the running lesson stays', after.id === before.id && after.step === before.step,
        `${after.id} step ${after.step}`);

  // 5. Links: a broken #lesson= is refused with its field; a good one opens its lesson.
  const badLink = base64url(Buffer.from(JSON.stringify({ lesson: 1, id: 'bad', title: 'B', summary: 'S', steps: [{ text: '' }] })));
  await page.evaluate((h) => { window.swarmlab.lastMessage = null; location.hash = h; }, '#lesson=' + badLink);
  await page.waitForFunction(() => window.swarmlab.lastMessage, null, { timeout: 10_000, polling: 50 }).catch(() => {});
  const linkMessage = await page.evaluate(() => window.swarmlab.lastMessage && window.swarmlab.lastMessage.text);
  check('a broken #lesson= link names the field', linkMessage === 'lesson link: steps[0].text: must not be empty', String(linkMessage));
  check('after a broken link the running lesson stays', (await api(page, 'lessonState')).id === before.id);
  const good = { lesson: 1, id: 'from-a-link', title: 'From a link', summary: 'S',
                 steps: [{ text: 'Hello *there*.', preset: 'two-body-circular.json', show: { plot: 'energy' } }] };
  await page.evaluate((h) => { location.hash = h; }, await api(page, 'lessonLink', good).then((u) => u.slice(u.indexOf('#'))));
  await page.waitForFunction(() => (window.swarmlab.lessonState() || {}).id === 'from-a-link', null, { timeout: 10_000, polling: 50 }).catch(() => {});
  check('a #lesson= link opens its lesson', (await api(page, 'lessonState')).id === 'from-a-link');

  // 5b. Share links: a shipped lesson by its id; anything that is not what Share writes is
  // refused with one sentence (never the JSON parser's own message, finding 4).
  const idLink = await api(page, 'lessonLink', 'one-period');
  check('lessonLink(id) links a shipped lesson by its id', idLink.endsWith('#lesson=one-period'), idLink);
  await page.evaluate((h) => { location.hash = h; }, '#lesson=one-period');
  await page.waitForFunction(() => (window.swarmlab.lessonState() || {}).id === 'one-period', null, { timeout: 10_000, polling: 50 }).catch(() => {});
  check('#lesson=<id> opens the shipped lesson', (await api(page, 'lessonState')).id === 'one-period');
  const copied = await api(page, 'copyLink');
  check('Copy link during a lesson copies the lesson link, in the language in use', copied.endsWith('#lang=en&lesson=one-period'), copied);
  const sentence = 'lesson link: the text after #lesson= is neither a shipped lesson\'s id (' + listedIds.join(', ') +
    ') nor a lesson written by Share (its JSON in base64url); the link may have been cut short';
  for (const bad of [base64url(Buffer.from('one-period')), 'no-such-lesson', 'x%%y']) {
    await page.evaluate((h) => { window.swarmlab.lastMessage = null; location.hash = h; }, '#lesson=' + bad);
    await page.waitForFunction(() => window.swarmlab.lastMessage, null, { timeout: 10_000, polling: 50 }).catch(() => {});
    const m = await page.evaluate(() => window.swarmlab.lastMessage && window.swarmlab.lastMessage.text);
    check(`#lesson=${bad.slice(0, 16)} is refused in one sentence`, m === sentence, String(m));
  }
  check('after refused links the lesson stays', (await api(page, 'lessonState')).id === 'one-period');

  // 5c. What gives an answer away is hidden until the task is answered (lesson 1, step 2).
  await api(page, 'lessonRestart');
  let hidden = await api(page, 'lessonNext');
  check('lesson 1 step 2 hides the read-outs and the card', hidden.hidden.readouts && hidden.hidden.card && !hidden.hidden.plots,
        JSON.stringify(hidden.hidden));
  await page.evaluate(() => window.swarmlab.lessonAnswer(window.swarmlab.lessonState().task.reading));
  hidden = await api(page, 'lessonState');
  check('answered right, they come back', !hidden.hidden.readouts && !hidden.hidden.card, JSON.stringify(hidden.hidden));
  // The API's feedback is the text the panel shows: the outcome's "{tap|click|click} another
  // ball" read for the device, not the lesson's markup (step 3's prediction).
  await api(page, 'lessonNext');
  const predicted = await api(page, 'lessonAnswer', 2);
  const shownFeedback = (await api(page, 'lessonState')).task.answered.feedback;
  for (const [where, f] of [['lessonAnswer', predicted.feedback], ['lessonState', shownFeedback]])
    check(`${where}'s feedback is plain text with the device's words`,
          /then (click|tap) another ball/.test(f) && !/[{}|*]/.test(f), f);
  await api(page, 'lessonBack');  // the pair again, for 5d

  // 5d. A step's run never ends while it is read: lesson 1's pair (its preset ends at t = 8.9)
  // runs on to t = 1000; lesson 5's Fig. 4 (ends at t = 3.2) loops.
  await api(page, 'set', { speed: 20 });
  await page.waitForFunction(() => window.swarmlab.state().t > 10, null, { timeout: 60_000, polling: 100 }).catch(() => {});
  let st5 = await api(page, 'state');
  check('lesson 1: the pair runs on past its preset\'s end', st5.t > 10 && st5.playing, `t = ${st5.t}, playing ${st5.playing}`);
  await api(page, 'openLesson', 'gas-at-the-wall');
  await api(page, 'lessonRestart');
  await api(page, 'set', { speed: 4 });
  // The app counts the times a step's run started again at its end (lessonState().loops).
  const loops = (await api(page, 'lessonState')).loops;
  await until(page, (n) => window.swarmlab.lessonState().loops > n, loops, 90_000);
  const looped = (await api(page, 'lessonState')).loops;
  const goesOn = await clockAdvances(page);
  st5 = await api(page, 'state');
  check('lesson 5: Fig. 4 starts again when it ends, and plays on', looped > loops && st5.playing && goesOn.ok,
        `loops ${loops} -> ${looped}, playing ${st5.playing}, ${goesOn.detail}`);
  await api(page, 'set', { speed: 1 });

  // 5e. Enter checks an answer, both Enter keys: on a page of its own at a phone's size, Tab to
  // the answer field (found by its name in the parallel DOM), type, Enter.
  const keys = await openApp(url, 'enter-key');
  await api(keys.page, 'openLesson', 'one-period');
  await api(keys.page, 'lessonRestart');
  await api(keys.page, 'lessonNext');
  await resize(keys.page, 390, 844);
  const lessonPanel = (await api(keys.page, 'state')).panels.find((p) => p.name === 'Lesson');
  check('the compact layout shows the Lesson tab', !!lessonPanel);
  if (lessonPanel) {
    const me = person(keys.page, 'keyboard');
    for (const [key, typed, right] of [['Enter', '4.44', true], ['NumpadEnter', '9', false]]) {
      await me.tabTo(me.find('textbox', 'Your answer'));
      await keys.page.keyboard.press('Control+A');
      await keys.page.keyboard.type(typed);
      await keys.page.keyboard.press(key);
      await until(keys.page, () => (window.swarmlab.lessonState().task || {}).answered);
      const answered = (await api(keys.page, 'lessonState')).task.answered;
      check(`${key} in the answer field checks it`, answered && answered.correct === right, JSON.stringify(answered));
      await drawn(keys.page, answered ? answered.feedback : '');
      await api(keys.page, 'lessonBack');
      await api(keys.page, 'lessonNext');  // a fresh step: no marking, an empty field
      // The page shows the fresh step (its feedback gone) before the next key.
      await until(keys.page, (f) => !document.getElementById('parallel-dom').textContent.includes(f), answered ? answered.feedback : '');
    }
  }
  await keys.page.close();

  // 5f. The panel and the summary as a student sees them, at a phone's, a tablet's and a
  // laptop's size in both themes (build/web-test/lessons-*.png), and presentation mode at
  // 1920x1080 showing the lesson.
  for (const theme of ['dark', 'light']) {
    await api(page, 'set', { theme });
    for (const [w, h] of [[390, 844], [820, 1180], [1366, 768]]) {
      await api(page, 'openLesson', 'gas-at-the-wall');
      await api(page, 'lessonRestart');
      await api(page, 'lessonNext');
      const { feedback } = await api(page, 'lessonAnswer', 2);  // a wrong option: feedback beside the options
      await resize(page, w, h);
      const shown = (await api(page, 'state')).panels.map((p) => p.name);
      check(`${w}x${h} ${theme}: the lesson is on screen`, shown.includes('Lesson') || shown.includes('Controls'), shown.join(', '));
      await drawn(page, feedback);
      await screenshot(page, `lessons-step-${w}x${h}-${theme}.png`);
      const done = await api(page, 'lessonFinish');
      check(`${w}x${h} ${theme}: Finish shows the summary`, done.summary === true);
      await drawn(page, 'Summary');
      await screenshot(page, `lessons-summary-${w}x${h}-${theme}.png`);
    }
  }
  await api(page, 'set', { theme: 'dark' });
  await api(page, 'lessonRestart');
  await api(page, 'set', { presentation: true });
  await resize(page, 1920, 1080);
  await until(page, () => window.swarmlab.state().panels.some((p) => p.name === 'Lesson'));
  const presenting = (await api(page, 'state')).panels.map((p) => p.name);
  check('presentation mode at 1920x1080 shows the lesson', presenting.includes('Lesson'), presenting.join(', '));
  await drawn(page, 'Step 1 of');
  await screenshot(page, 'lessons-presentation-1920x1080.png');
  await api(page, 'set', { presentation: false });
  await resize(page, 1280, 720);
  await api(page, 'openLesson', 'one-period');
  await api(page, 'lessonRestart');
  for (let i = 0; i < lessonById['one-period'].steps.length - 2; ++i) await api(page, 'lessonNext');

  // 6. The second visit: no welcome, and the lesson progress is still there.
  const second = await openApp(url + '?welcome', 'second-visit');
  check('the welcome does not show on the second visit', second.started && !(await api(second.page, 'welcomeShown')));
  await api(second.page, 'openLesson', 'one-period');
  const resumed = await api(second.page, 'lessonState');
  check('a lesson reopens where it was left', resumed.step === lessonById['one-period'].steps.length - 2, String(resumed.step));

  check('no page errors', pageErrors.length === 0, pageErrors.slice(0, 3).join(' | '));
  check('no console errors', consoleErrors.length === 0, consoleErrors.slice(0, 3).join(' | '));
}

runSuite('lessons', 280_000, main);
