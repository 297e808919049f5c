// Storage that says what it does, and seeks that never freeze the page (issue 26).
// Progress: localStorage.setItem throwing (a full quota, a private window), storage blocked (even
// reading window.localStorage throws), a record that cannot be read, and one from a newer
// version: each says so once (the notice window, which the parallel DOM mirrors, and the live
// region), and what was stored is kept (set aside under another key, or left alone). A person
// downloads the progress from the notice and loads it again in a new visit, pressing buttons
// found by role and name in the parallel DOM. Seeks (tests of the JS API itself): a far seek
// answers at once with a Promise while frames keep coming, its progress is shown and reported,
// no main-thread task takes 100 ms or more (PerformanceObserver 'longtask'), it settles with the
// time reached; a target beyond the run is refused with its rule and changes nothing; a new
// seek, or a person's Cancel, cancels one. Every wait is on a condition: the machine may be
// loaded.
import { readFileSync } from 'node:fs';
import * as harness from './harness.mjs';
import { person } from './person.mjs';

const { check, shipped, openApp, launchBrowser, closeBrowser, runSuite, keepsDrawing, pageErrors } = harness;

const NOT_SAVED = 'Your lesson progress cannot be saved here';
const UNREADABLE = 'Your saved lesson progress could not be read, so lessons start afresh';
const NEWER = 'Your lesson progress was saved by a newer version of Swarm Lab';
const LESSON = JSON.parse(readFileSync(new URL('../../assets/lessons/01-one-period.json', import.meta.url), 'utf8'));

// In the page before its scripts: every text the live region takes, and the long tasks.
const listen = `(${harness.recordLiveRegion})(); (${recordLongTasks})();`;
function recordLongTasks() {
  window.longTasks = [];
  try {
    new PerformanceObserver((list) => {
      for (const e of list.getEntries()) window.longTasks.push({ start: e.startTime, ms: e.duration });
    }).observe({ type: 'longtask', buffered: true });
  } catch (e) { window.longTasks = null; }
}

// Storage as each fault leaves it, set up before the page's own scripts (one page each).
const faults = {
  quota: () => {
    localStorage.clear();
    Storage.prototype.setItem = function () {
      throw new DOMException('The quota has been exceeded.', 'QuotaExceededError');
    };
  },
  blocked: () => {
    Object.defineProperty(window, 'localStorage', {
      configurable: true,
      get() { throw new DOMException('Access is denied for this document.', 'SecurityError'); },
    });
  },
  corrupt: () => {
    localStorage.clear();
    localStorage.setItem('swarmlab.progress', '{"version": 1, "welcomed": true, "lessons": {"one-per');
  },
  newer: () => {
    localStorage.clear();
    localStorage.setItem('swarmlab.progress', '{"version": 99, "welcomed": true, "lessons": {"future": {"stars": 3}}}');
  },
};

/** Opens the page with `fault` and `listen` in place, a first visit (no progress put in). */
async function openWith(url, fault, label) {
  const init = `${listen} (${faults[fault] || (() => {})})();`;
  return openApp(`${url}?welcome`, label, init);
}

/** Lesson 1 opened as a person does, from the Lessons menu (it resumes where it was left). */
async function openLessonOne(page, me) {
  await me.press('menuitem', 'Lessons');
  await me.press('menuitem', LESSON.title);
  await page.waitForFunction((id) => window.swarmlab.lessonState()?.id === id, LESSON.id, { timeout: 30_000 });
}

const said = (page) => page.evaluate(() => window.liveRegionSaid);
const untilSaid = (page, text) => page.waitForFunction((t) => window.liveRegionSaid.some((s) => s.includes(t)), text,
                                                       { timeout: 30_000 }).then(() => true, () => false);
// The page's message line (#notice, role status: a live region of its own).
const noticeSays = (page, text) => page.waitForFunction((t) => {
  const box = document.getElementById('notice');
  return !box.hidden && document.getElementById('notice-text').textContent.includes(t);
}, text, { timeout: 30_000 }).then(() => true, () => false);
const inDom = (me, text) => me.dom.getByText(text, { exact: false }).first().waitFor({ state: 'attached', timeout: 30_000 })
  .then(() => true, () => false);
const stored = (page) => page.evaluate(() => {
  const all = {};
  for (let i = 0; i < localStorage.length; ++i) all[localStorage.key(i)] = localStorage.getItem(localStorage.key(i));
  return all;
});

async function faultsSaid(url) {
  await launchBrowser({ width: 1280, height: 720 });
  // 1. setItem throws: said once, in the window and aloud; the app goes on.
  let { page, started, error } = await openWith(url, 'quota', 'storage-quota');
  if (check('setItem throwing: the app starts', started, error || '')) {
    const me = person(page, 'mouse');
    check('setItem throwing: the notice says progress cannot be saved', await inDom(me, NOT_SAVED));
    check('setItem throwing: the live region says it', await untilSaid(page, NOT_SAVED));
    check('setItem throwing: the notice offers Download progress and Load progress...',
          await me.find('button', 'Download progress').count() === 1 && await me.find('button', 'Load progress...').count() === 1);
    const drawn = await keepsDrawing(page);
    check('setItem throwing: said once, and the app draws on', drawn.ok &&
          (await said(page)).filter((s) => s.includes(NOT_SAVED)).length === 1, drawn.detail);
  }
  await page.close();

  // 2. Storage blocked: window.localStorage itself throws.
  ({ page, started, error } = await openWith(url, 'blocked', 'storage-blocked'));
  if (check('storage blocked: the app starts', started, error || '')) {
    const me = person(page, 'mouse');
    check('storage blocked: the notice says progress cannot be saved', await inDom(me, NOT_SAVED));
    const heard = await untilSaid(page, NOT_SAVED);
    const drawn = await keepsDrawing(page);  // frames after the first saying, for a repeat to show
    check('storage blocked: the live region says it once', heard && drawn.ok &&
          (await said(page)).filter((s) => s.includes(NOT_SAVED)).length === 1, drawn.detail);
  }
  await page.close();

  // 3. A record that cannot be read: kept aside under another key, lessons start afresh.
  ({ page, started, error } = await openWith(url, 'corrupt', 'storage-corrupt'));
  if (check('a corrupt record: the app starts', started, error || '')) {
    const me = person(page, 'mouse');
    check('a corrupt record: the notice says it could not be read and is kept aside',
          await inDom(me, UNREADABLE) && await untilSaid(page, UNREADABLE));
    const all = await stored(page);
    const aside = Object.keys(all).filter((k) => k.startsWith('swarmlab.progress.unreadable-'));
    check('a corrupt record: kept whole under swarmlab.progress.unreadable-<time>', aside.length === 1 &&
          all[aside[0]] === '{"version": 1, "welcomed": true, "lessons": {"one-per', aside.join(', '));
    check('a corrupt record: the notice names where it is kept', aside.length === 1 && await inDom(me, aside[0]));
    let fresh = null;
    try { fresh = JSON.parse(all['swarmlab.progress']); } catch { /* checked below */ }
    check('a corrupt record: a readable record in its place', fresh && fresh.version === 1, all['swarmlab.progress']);
  }
  await page.close();

  // 4. A newer version's record: left alone while a lesson is opened and moved on.
  ({ page, started, error } = await openWith(url, 'newer', 'storage-newer'));
  if (check('a newer record: the app starts', started, error || '')) {
    const me = person(page, 'mouse');
    check('a newer record: the notice says a newer version saved it and it is left alone',
          await inDom(me, NEWER) && await untilSaid(page, NEWER));
    const before = (await stored(page))['swarmlab.progress'];
    await openLessonOne(page, me);
    await me.press('button', /^Next \u2192/);
    await page.waitForFunction(() => window.swarmlab.lessonState()?.step === 1, null, { timeout: 30_000 }).catch(() => {});
    const after = await stored(page);
    check('a newer record: not written over while the student works', after['swarmlab.progress'] === before &&
          (await page.evaluate(() => window.swarmlab.lessonState().step)) === 1, after['swarmlab.progress']);
    check('a newer record: the welcome does not return', !(await page.evaluate(() => window.swarmlab.welcomeShown())));
  }
  await page.close();
  await closeBrowser();
}

// A person keeps progress that the browser will not: downloads it, and loads it next visit.
async function downloadAndLoad(url) {
  await launchBrowser({ width: 1280, height: 720 });
  let { page, started, error } = await openWith(url, 'quota', 'storage-download');
  if (!check('download: the app starts', started, error || '')) return;
  let me = person(page, 'mouse');
  await inDom(me, NOT_SAVED);
  await me.press('button', 'Just the simulation');  // the welcome (a first visit, every visit)
  // Progress: lesson 1 opened from the Lessons menu and moved on a step.
  await openLessonOne(page, me);
  await me.press('button', /^Next \u2192/);
  await page.waitForFunction(() => window.swarmlab.lessonState()?.step === 1, null, { timeout: 30_000 });
  await me.press('menuitem', 'Lessons');
  const [download] = await Promise.all([page.waitForEvent('download', { timeout: 30_000 }).catch(() => null),
                                        me.press('menuitem', 'Download progress')]);
  const file = download ? readFileSync(await download.path(), 'utf8') : '';
  let record = null;
  try { record = JSON.parse(file); } catch { /* checked below */ }
  check('Download progress: a JSON file with the lesson\'s step', record && record.version === 1 &&
        record.lessons?.[LESSON.id]?.step === 1, download ? `${download.suggestedFilename()}: ${file.slice(0, 120)}` : 'no download');
  await page.close();

  // The next visit: nothing kept (storage still refuses), the notice again; Load progress...
  ({ page, started, error } = await openWith(url, 'quota', 'storage-load'));
  if (!check('load: the app starts again', started, error || '')) return;
  me = person(page, 'keyboard');
  await inDom(me, NOT_SAVED);
  const [chooser] = await Promise.all([page.waitForEvent('filechooser', { timeout: 30_000 }).catch(() => null),
                                       me.press('button', 'Load progress...')]);
  if (!check('Load progress...: a file picker opens', !!chooser)) return;
  await chooser.setFiles({ name: 'swarmlab-progress.json', mimeType: 'application/json', buffer: Buffer.from(file) });
  check('Load progress...: the message line (a live region) says it was loaded', await noticeSays(page, 'Lesson progress loaded from the file.'));
  me = person(page, 'mouse');
  await me.press('button', 'Just the simulation');
  const resumed = await openLessonOne(page, me).then(() => page.evaluate(() => window.swarmlab.lessonState().step), () => null);
  check('Load progress...: the lesson resumes at the step of the file', resumed === 1, `step ${resumed}`);
  // A file that is no progress is refused with a reason, and nothing changes.
  const [again] = await Promise.all([page.waitForEvent('filechooser', { timeout: 30_000 }).catch(() => null),
                                     (async () => { await me.press('menuitem', 'Lessons'); await me.press('menuitem', 'Load progress...'); })()]);
  if (again) {
    await again.setFiles({ name: 'preset.json', mimeType: 'application/json', buffer: Buffer.from(JSON.stringify(shipped('fig1-four-masses.json'))) });
    check('Load progress...: a preset file is refused, saying why', await noticeSays(page, 'This file is not Swarm Lab lesson progress.'));
  } else check('Load progress... from the Lessons menu: a file picker opens', false);
  await page.close();
  await closeBrowser();
}

// The JS API's seek, bounded.
async function seeks(url) {
  await launchBrowser({ width: 1280, height: 720 });
  const { page, started, error } = await openApp(url, 'storage-seek', listen);
  if (!check('seek: the app starts', started, error || '')) return;
  const api = (fn, ...args) => page.evaluate(fn, ...args);
  await api((p) => window.swarmlab.load(p), shipped('fig5-long-equilibration.json'));
  const tEnd = (await api(() => window.swarmlab.state())).timeline.t_end;

  // 1. Refused beyond the run: one message naming t and the rule; nothing changes.
  await api(() => window.swarmlab.set({ playing: false }));
  const before = await api(() => ({ t: window.swarmlab.time(), playing: window.swarmlab.state().playing }));
  const refused = await api((t) => window.swarmlab.seek(t).then(() => null, (e) => e.message), 1e9);
  const after = await api(() => ({ t: window.swarmlab.time(), seek: window.swarmlab.state().seek }));
  const rule = /^swarmlab\.seek\(t\): t = 1000000000 is beyond the run: t must be from 0 to the end of the preset's run, t = (\S+)$/
    .exec(refused || '');
  check('seek(1e9) is refused with its rule', rule && Math.abs(Number(rule[1]) - tEnd) < 1e-6 * tEnd, refused);
  check('a refused seek changes nothing', after.seek === null && after.t === before.t && !before.playing, JSON.stringify(after));
  const negative = await api(() => window.swarmlab.seek(-1).then(() => null, (e) => e.message));
  check('seek(-1) is refused too', /t = -1 is beyond the run/.test(negative || ''), negative);
  // Not a number: the message shows what was given, its kind too (a bare 5 would read as a number).
  const given = await api(() => Promise.all(['5', undefined, NaN, null, [2]].map(
    (t) => window.swarmlab.seek(t).then(() => null, (e) => e.message))));
  const said = ['the string "5"', 'undefined', 'NaN', 'null', 'an array'];
  check('seek(\'5\'), seek(), seek(NaN), seek(null), seek([2]): each refused showing what was given',
        given.every((m, i) => m === 'swarmlab.seek(t): t must be a finite number (time units), got ' + said[i]), given.join(' | '));

  // 2. A far seek: answered at once with a Promise; frames keep coming; progress shown. First
  // the page's own long tasks over as many frames while it plays (the run changing every frame,
  // as in a seek): what this machine costs such a frame now.
  const FRAMES = 20;
  await api(() => { window.swarmlab.set({ playing: true }); window.longTasks.length = 0; });
  const playing = await keepsDrawing(page, FRAMES, 60_000);
  const playingTasks = await api(() => { window.swarmlab.set({ playing: false }); return window.longTasks; });
  const playingLongest = playingTasks ? Math.max(0, ...playingTasks.map((x) => x.ms)) : null;
  await api(() => { window.longTasks.length = 0; });
  const answered = await api((t) => {
    window.seekProgress = [];
    window.seekStartedAt = performance.now();
    const t0 = performance.now();
    const p = window.swarmlab.seek(t, { onprogress: (e) => window.seekProgress.push(e.progress) });
    window.farSeek = p.then((v) => ({ t: v }), (e) => ({ error: e.message, name: e.name, cancelled: e.cancelled, t: e.t }));
    return { ms: performance.now() - t0, promise: p instanceof Promise };
  }, tEnd);
  check('a far seek answers within 100 ms with a Promise', answered.promise && answered.ms < 100, `${answered.ms.toFixed(1)} ms`);
  const frames = await keepsDrawing(page, FRAMES, 60_000);
  const during = await api(() => window.swarmlab.state());
  check('frames keep coming while it runs', frames.ok && during.seek !== null, `${frames.detail}; seek ${JSON.stringify(during.seek)}`);
  await page.waitForFunction(() => window.seekProgress.some((p) => p > 0), null, { timeout: 30_000 }).catch(() => {});
  const progress = await api(() => window.seekProgress);
  const rising = progress.every((p, i) => p >= 0 && p <= 1 && (i === 0 || p >= progress[i - 1]));
  const bar = await api(() => window.swarmlab.state().last_fast_forward);
  check('its progress is reported (onprogress, state().seek) and shown as a fast-forward\'s',
        progress.some((p) => p > 0 && p < 1) && rising && during.seek.t === tEnd && bar && bar.kind === 'time' && bar.frames > 0,
        `${progress.length} reports, last ${progress.at(-1)}; bar ${bar && bar.frames} frames`);

  // 3. A person's Cancel (the progress bar's button, found in the parallel DOM) cancels it.
  const me = person(page, 'mouse');
  await api(() => { window.cancelPressedAt = performance.now(); });
  await me.press('button', 'Cancel');
  const cancelled = await api(() => window.farSeek);
  check('Cancel: the seek\'s Promise rejects, cancelled, with the time then', cancelled.name === 'AbortError' &&
        cancelled.cancelled === true && cancelled.t > 0 && cancelled.t < tEnd, JSON.stringify(cancelled));
  const tasks = await api(() => window.longTasks);
  const [startedAt, cancelAt] = await api(() => [window.seekStartedAt, window.cancelPressedAt]);
  const longest = tasks ? Math.max(0, ...tasks.map((x) => x.ms)) : null;
  const record = await api(() => window.swarmlab.state().last_fast_forward);
  check('the seek\'s own work in a frame stays within its budget (40 ms; under 100 ms of wall time)',
        record && record.kind === 'time' && record.longest_ms > 0 && record.longest_ms < 100,
        record && `longest ${record.longest_ms.toFixed(1)} ms over ${record.frames} frames`);
  // A machine loaded past its cores stretches every task, the page's playing frames too (on 2
  // cores at a load of 15, up to 300 ms): there the seek may add to a frame no more than the
  // 100 ms it is allowed, over the longest frame of the page playing, measured just before.
  check('no main-thread task of 100 ms or more while it ran (where playing frames alone take longer: none longer than they do + 100 ms)',
        tasks !== null && playing.ok && longest < Math.max(100, playingLongest + 100),
        tasks === null ? 'no longtask observer' : `seeking: ${tasks.length} tasks over 50 ms, longest ${longest.toFixed(0)} ms ` +
        `(at ${tasks.length ? (tasks.find((x) => x.ms === longest).start - startedAt).toFixed(0) : '-'} ms after the seek; Cancel pressed at ${(cancelAt - startedAt).toFixed(0)} ms); ` +
        `playing (${playing.detail}): ${playingTasks.length} tasks over 50 ms, longest ${playingLongest.toFixed(0)} ms`);

  // 4. A new seek cancels the one under way; the new one settles at its time.
  const near = Math.min(tEnd, (cancelled.t || 0) + 2);
  const pair = await api(([far, near]) => {
    const first = window.swarmlab.seek(far).then((v) => ({ t: v }), (e) => ({ name: e.name, cancelled: e.cancelled }));
    const second = window.swarmlab.seek(near).then((v) => ({ t: v }), (e) => ({ error: e.message }));
    return Promise.all([first, second]);
  }, [tEnd, near]);
  check('a new seek cancels the one under way', pair[0].name === 'AbortError' && pair[0].cancelled === true, JSON.stringify(pair[0]));
  check('the new seek settles with the time reached', Math.abs(pair[1].t - near) < 0.011, JSON.stringify(pair[1]));
  const tNow = await api(() => window.swarmlab.time());
  check('and the run is there', Math.abs(tNow - pair[1].t) < 1e-6, `t = ${tNow}`);
  check('no page errors', pageErrors.length === 0, pageErrors.join(' | '));
  await page.close();
  await closeBrowser();
}

async function main(url) {
  await faultsSaid(url);
  await downloadAndLoad(url);
  await seeks(url);
}

runSuite('storage_e2e', 140_000, main);
