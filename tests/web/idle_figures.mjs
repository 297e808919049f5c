// What the page costs while a class looks at it: the main thread's busy fraction and the
// frames per second at 1366x768, playing and then paused, each over a window of wall time
// (10 s unless --seconds N). The busy fraction is Chrome's own count of the main thread's task
// time (DevTools Protocol Performance.getMetrics, TaskDuration) over the wall time between two
// readings; the frames are those drawn (state().frames_drawn; before the app counted them,
// swarmlab.frames(), the requestAnimationFrame callbacks it ran, each of which drew).
// The page is served as a class gets it (scripts/web.sh --no-build) and opened as a returning
// student opens it (the default preset, playing); Pause is pressed with the mouse through the
// parallel DOM, as a person would, and the pointer stays where it pressed. The load average
// is read at the start and the end of each window: run it with nothing else of yours busy.
// A measurement, not a test: it prints the figures and writes build/web-test/idle_figures.json.
//   node tests/web/idle_figures.mjs [--seconds N]   (after scripts/web.sh --build-only)
import { execSync } from 'node:child_process';
import { writeFileSync } from 'node:fs';
import { loadavg } from 'node:os';
import { join } from 'node:path';
import { root, outDir, startWebServer, launchBrowser, openApp, cleanup, sleep, context, pageMetrics } from './harness.mjs';
import { person } from './person.mjs';

const at = process.argv.indexOf('--seconds');
const SECONDS = at > 0 ? Number(process.argv[at + 1]) : 10;
const VIEWPORT = { width: 1366, height: 768 };
const load = () => loadavg().map((x) => +x.toFixed(2));
const git = (args) => execSync(`git ${args}`, { cwd: root, encoding: 'utf8' }).trim();

// One window: the main thread's busy fraction and the frames per second over SECONDS.
async function measure(page, cdp, what) {
  const metric = () => pageMetrics(cdp);
  const loadStart = load();
  // Frames drawn (state().frames_drawn where the app counts them apart from the main loop's
  // runs, which go on while it idles), and whether the app says it idles.
  const frames = () => page.evaluate(() => {
    const s = window.swarmlab.state();
    return { drawn: s.frames_drawn ?? window.swarmlab.frames(), idle: s.idle ?? null };
  });
  const m0 = await metric(), f0 = await frames();
  await sleep(SECONDS * 1000);
  const m1 = await metric(), f1 = await frames();
  const wall = m1.Timestamp - m0.Timestamp;  // seconds, the browser's clock
  const figures = { what, seconds: +wall.toFixed(2), busy: +((m1.TaskDuration - m0.TaskDuration) / wall).toFixed(3),
                    scriptBusy: +((m1.ScriptDuration - m0.ScriptDuration) / wall).toFixed(3),
                    fps: +((f1.drawn - f0.drawn) / wall).toFixed(1), idle: [f0.idle, f1.idle], load: { start: loadStart, end: load() } };
  console.log(`${what.padEnd(8)} main thread busy ${(100 * figures.busy).toFixed(1).padStart(5)} % ` +
              `(script ${(100 * figures.scriptBusy).toFixed(1)} %), ${figures.fps.toFixed(1).padStart(5)} frames/s drawn ` +
              `over ${figures.seconds} s${f1.idle === null ? '' : `, idle ${f0.idle} -> ${f1.idle}`}; ` +
              `load average ${figures.load.start.join(' ')} -> ${figures.load.end.join(' ')}`);
  return figures;
}

async function main() {
  const url = await startWebServer();
  await launchBrowser(VIEWPORT);
  const { page, started, error } = await openApp(url, 'idle');
  if (!started) throw new Error('the app did not start: ' + error);
  const cdp = await context.newCDPSession(page);
  await cdp.send('Performance.enable', { timeDomain: 'timeTicks' });
  const me = person(page, 'mouse');
  const report = { date: new Date().toISOString(), commit: git('rev-parse --short HEAD') + (git('status --porcelain --untracked-files=no') ? ' (with changes)' : ''),
                   viewport: VIEWPORT, windows: [] };
  if (!(await me.find('button', /Pause/).count())) await me.press('button', /Play/);
  await page.waitForFunction(() => window.swarmlab.state().playing);
  report.windows.push(await measure(page, cdp, 'playing'));
  await me.press('button', /Pause/);
  await page.waitForFunction(() => !window.swarmlab.state().playing);
  // Where the app says when it idles, the window starts once it does (it settles in a few
  // frames), or after 30 s if it never does (the figures then say so).
  const t0 = Date.now();
  const settled = await page.waitForFunction(() => window.swarmlab.state().idle !== false, null, { timeout: 30_000 })
    .then(() => true, () => false);
  report.settleMs = Date.now() - t0;
  console.log(`paused: ${settled ? 'idle' : 'not idle'} after ${report.settleMs} ms`);
  report.windows.push(await measure(page, cdp, 'paused'));
  writeFileSync(join(outDir, 'idle_figures.json'), JSON.stringify(report, null, 2) + '\n');
  console.log(`commit ${report.commit}, ${report.date}; build/web-test/idle_figures.json`);
}

let status = 0;
try { await main(); } catch (e) { console.error('idle_figures:', e); status = 1; }
await cleanup();
process.exit(status);
