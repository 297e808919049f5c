// Files dropped on the page (web/swarmlab_api.js's drop handler), as a person drags them from
// the desktop: a real drop event with a DataTransfer holding the file, on the app's canvas. A
// lesson file opens as a lesson, not as a preset that breaks the preset rules ("id: unknown
// key"); a preset file runs; a file that is not JSON, or holds a NUL byte, gets one line that
// names the file, where it breaks and what is wrong, never the parser's own
// "[json.exception.parse_error.101]", and the running preset goes on.
// window.swarmlab is only read.
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import * as harness from './harness.mjs';

const { root, check, openApp, launchBrowser, runSuite, shipped, state, clockAdvances, pageErrors } = harness;

const lessonText = readFileSync(join(root, 'assets/lessons/02-springs-to-cm.json'), 'utf8');
const lesson = JSON.parse(lessonText);

/** Drops a file `name` holding `text` on the canvas: dragenter, dragover and drop, each with
 *  the same DataTransfer, as the browser sends them when a person lets go of a file. */
async function dropFile(page, name, text) {
  const transfer = await page.evaluateHandle(([n, t]) => {
    const dt = new DataTransfer();
    dt.items.add(new File([t], n, { type: 'application/json' }));
    return dt;
  }, [name, text]);
  for (const type of ['dragenter', 'dragover', 'drop'])
    await page.dispatchEvent('canvas', type, { dataTransfer: transfer });
  await transfer.dispose();
}

const until = (page, fn, arg = null) => page.waitForFunction(fn, arg, { timeout: 20_000 }).then(() => true, () => false);
// The message the page shows (the notice a person reads), once it names `file`.
async function noticeFor(page, file) {
  await until(page, (f) => {
    const n = document.getElementById('notice');
    return !n.hidden && document.getElementById('notice-text').textContent.includes(f);
  }, file);
  return (await state(page)).notice;
}

async function main(url) {
  await launchBrowser({ width: 1280, height: 720 });
  const { page, started, error } = await openApp(url, 'drop');
  if (!check('the app starts', started, error || '')) return;

  // 1. A lesson file: it opens as the lesson, its title in the lesson panel.
  await dropFile(page, 'springs.json', lessonText);
  const opened = await until(page, (id) => window.swarmlab.lessonState()?.id === id, lesson.id);
  const shown = await until(page, (t) => document.getElementById('parallel-dom').textContent.includes(t), lesson.title);
  const notice = (await state(page)).notice;
  check('a dropped lesson file opens as the lesson, its title shown', opened && shown && !/unknown key/.test(notice),
        `${await page.evaluate(() => window.swarmlab.lessonState()?.id)}${notice ? ', notice: ' + notice : ''}`);

  // 2. A lesson file that breaks a lesson rule: the lesson's message, naming the file.
  const broken = JSON.parse(lessonText);
  broken.steps[0].text = '\u202e';
  await dropFile(page, 'broken-lesson.json', JSON.stringify(broken));
  const brokenSays = await noticeFor(page, 'broken-lesson.json');
  check('a dropped lesson that breaks a rule gets the lesson\'s message, not a preset\'s',
        /^broken-lesson\.json: steps\[0\]\.text: must show something/.test(brokenSays) &&
        await page.evaluate((id) => window.swarmlab.lessonState()?.id === id, lesson.id), brokenSays);

  // 3. A preset file still runs as a preset.
  const preset = { ...shipped('two-body-circular.json'), name: 'Dropped preset' };
  await dropFile(page, 'dropped.json', JSON.stringify(preset, null, 2));
  check('a dropped preset file runs', await until(page, () => JSON.parse(window.swarmlab.preset()).name === 'Dropped preset'));

  // 4. A file with a NUL byte, and one cut short: one line naming the file, the place and the
  //    fault, and the dropped preset keeps running.
  const withNul = '{"name": "x",\u0000 "J": 1}';
  await dropFile(page, 'with-nul.json', withNul);
  const nulSays = await noticeFor(page, 'with-nul.json');
  check('a NUL byte: named with its offset, not the parser\'s code',
        /^with-nul\.json: preset: a NUL byte at offset 13 /.test(nulSays) && !/json\.exception/.test(nulSays) &&
        !nulSays.includes('\n'), nulSays);
  const cut = JSON.stringify(preset, null, 2).slice(0, 60);
  await dropFile(page, 'cut-short.json', cut);
  const cutSays = await noticeFor(page, 'cut-short.json');
  check('text cut short: "not valid JSON at line L, column C: what is wrong"',
        /^cut-short\.json: preset: not valid JSON at line \d+, column \d+: \S/.test(cutSays) &&
        !/json\.exception/.test(cutSays) && !cutSays.includes('\n'), cutSays);
  const lessonNul = lessonText.replace('"title"', '\u0000"title"');
  await dropFile(page, 'lesson-nul.json', lessonNul);
  const lessonNulSays = await noticeFor(page, 'lesson-nul.json');
  check('a lesson file with a NUL byte: named with its offset', /^lesson-nul\.json: lesson: a NUL byte at offset \d+/.test(lessonNulSays),
        lessonNulSays);
  const going = await clockAdvances(page);
  check('the dropped preset keeps running after the refusals',
        JSON.parse(await page.evaluate(() => window.swarmlab.preset())).name === 'Dropped preset' && going.ok, going.detail);
  check('no page errors', pageErrors.length === 0, pageErrors.join(' | '));
}

await runSuite('drop', 60_000, main);
