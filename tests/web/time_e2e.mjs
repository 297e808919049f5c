// Browser checks of time travel (issue 13): swarmlab.seek(t) (a Promise of the time reached,
// awaited through page.evaluate; its bounds are tests/web/storage_e2e.mjs's) back and forth lands on the same
// positions() to the last digit, with a container too; on the isolated Fig. 1 preset a seek
// gives the analytic solution (computed here, independently) and the positions of a fresh run
// taken to the same time; state().t_reached; the End key fast-forwards with its progress
// shown over several frames (the app's record of it, state().last_fast_forward), and finishes
// at the run's end. Every wait is on the state an action produces: the machine may be loaded.
import * as harness from './harness.mjs';

const { check, shipped, openApp, launchBrowser, runSuite, keepsDrawing, pageErrors, consoleErrors } = harness;

async function main(url) {
  await launchBrowser({ width: 1280, height: 720 });
  const { page, started, error } = await openApp(url, 'time');
  if (!check('the app starts', started, error || '')) return;
  const api = (fn, ...args) => page.evaluate(fn, ...args);
  const same = (a, b) => JSON.stringify(a) === JSON.stringify(b);

  // 1. The isolated Fig. 1 preset: back and forth, and the analytic solution.
  const fig1 = shipped('fig1-four-masses.json');
  await api((p) => window.swarmlab.load(p), fig1);
  const tForward = await api(() => window.swarmlab.seek(6.0));
  check('seek(6) forward returns the time reached', Math.abs(tForward - 6.0) < 1e-9, `t = ${tForward}`);
  const at6 = await api(() => window.swarmlab.positions());
  check('positions() gives one [x, y, z] per particle', at6.length === 4 && at6[0].length === 3);
  const tBack = await api(() => window.swarmlab.seek(1.25));
  const at125 = await api(() => window.swarmlab.positions());
  await api(() => window.swarmlab.seek(6.0));
  const again6 = await api(() => window.swarmlab.positions());
  check('seek(1.25) back returns the time reached', Math.abs(tBack - 1.25) < 1e-9, `t = ${tBack}`);
  check('seek back then forward lands on identical positions', same(at6, again6));
  const s = await api(() => window.swarmlab.state());
  check('state().t_reached is the furthest time computed', Math.abs(s.t_reached - 6.0) < 1e-9 && s.t === tForward && !s.playing,
        `t_reached ${s.t_reached}, t ${s.t}, playing ${s.playing}`);

  // x_i(t) = R_cm(t) + (x_i0 - R_cm0) cos(w t) + (v_i0 - V_cm) sin(w t) / w, w = sqrt(J M).
  const M = fig1.particles.reduce((m, p) => m + p.m, 0), w = Math.sqrt(fig1.J * M);
  const cm = (key) => [0, 1, 2].map((k) => fig1.particles.reduce((sum, p) => sum + p.m * p[key][k], 0) / M);
  const R0 = cm('r'), V = cm('v');
  const exact = (t) => fig1.particles.map((p) => [0, 1, 2].map((k) =>
    R0[k] + V[k] * t + (p.r[k] - R0[k]) * Math.cos(w * t) + (p.v[k] - V[k]) * Math.sin(w * t) / w));
  const worst = (a, b) => Math.max(...a.flatMap((r, i) => r.map((x, k) => Math.abs(x - b[i][k]))));
  check('an isolated system sought to t = 1.25 is the analytic solution', worst(at125, exact(1.25)) < 1e-9,
        `max |r - r_exact| = ${worst(at125, exact(1.25)).toExponential(2)}`);
  check('and at t = 6', worst(again6, exact(6.0)) < 1e-9, `max |r - r_exact| = ${worst(again6, exact(6.0)).toExponential(2)}`);
  await api((p) => window.swarmlab.load(p), fig1);  // a fresh run
  await api(() => window.swarmlab.seek(6.0));
  check('a fresh run taken to t = 6 has the same positions', same(await api(() => window.swarmlab.positions()), at6));

  // 2. A container (the fast engine's snapshots): played, then sought back and forth.
  const box = { version: 1, name: 'time test box', J: 1.0 / 2250,
                particles: { count: 500, mass: { min: 4, max: 5 }, position_radius: 1, velocity: { speed: 1.5 }, seed: 7 },
                container: { radius: 1 }, dt: 0.001, duration: 3 };
  await api((p) => window.swarmlab.load(p), box);
  await api(() => window.swarmlab.seek(2.0));
  const first = await api(() => window.swarmlab.positions());
  await api(() => window.swarmlab.seek(0.3));
  const early = await api(() => window.swarmlab.positions());
  await api(() => window.swarmlab.seek(2.9));
  await api(() => window.swarmlab.seek(2.0));
  check('with a container, seek back and forth lands on identical positions', same(first, await api(() => window.swarmlab.positions())));
  await api(() => window.swarmlab.seek(0.3));
  check('and at an early time too', same(early, await api(() => window.swarmlab.positions())) && !same(early, first));

  // 3. Fast-forward to the end of the run: End, its progress bar frame by frame, the end. Twelve
  // stages of 100: work for several frames' budgets on a fast machine.
  const ff = { ...shipped('fig2-attractive-expansion.json'), name: 'time test expansion' };
  ff.expansion = { ...ff.expansion, stages: 12, tau: 100 };
  const tEnd = ff.expansion.stages * ff.expansion.tau;
  await api((p) => window.swarmlab.load(p), ff);
  await page.mouse.click(620, 300);  // focus the canvas
  // The longest stall of the page's main thread while it runs, from a 20 ms interval timer.
  await api(() => {
    const s = window.__stall = { last: performance.now(), longest: 0 };
    s.timer = setInterval(() => { const now = performance.now(); s.longest = Math.max(s.longest, now - s.last); s.last = now; }, 20);
  });
  const pressed = Date.now();
  await page.keyboard.press('End');
  await page.waitForFunction(() => { const s = window.swarmlab.state(); return s.last_fast_forward && !s.fast_forward; },
                             null, { timeout: 60_000 }).catch(() => {});
  const ms = Date.now() - pressed;
  const stall = await api(() => { clearInterval(window.__stall.timer); return window.__stall.longest; });
  const endState = await api(() => window.swarmlab.state());
  const record = endState.last_fast_forward;
  const shown = record ? record.progress : [];
  const rising = shown.every((p, i) => p >= 0 && p <= 1 && (i === 0 || p >= shown[i - 1]));
  check('End fast-forwards with its progress shown frame by frame', record && record.kind === 'run_end' && record.frames >= 3 &&
        shown.some((p) => p > 0 && p < 1) && rising,
        record ? `${record.frames} frames in ${ms} ms, progress ${shown.map((p) => p.toFixed(2)).join(' ')}` : 'no fast-forward');
  check('the fast-forward finishes at the end of the run', record && record.reached && Math.abs(endState.t - tEnd) < 1e-6 &&
        Math.abs(endState.t_reached - tEnd) < 1e-6, `t = ${endState.t}, t_reached ${endState.t_reached}, reached ${record && record.reached}`);
  const drawing = await keepsDrawing(page);
  check('the window kept answering while it ran (longest stall under 1.5 s), and draws on', stall < 1500 && drawing.ok,
        `longest stall ${stall.toFixed(0)} ms; ${drawing.detail}`);

  check('no page errors', pageErrors.length === 0, pageErrors.join(' | '));
  check('no console errors', consoleErrors.length === 0, consoleErrors.join(' | '));
}

runSuite('time_e2e', 140_000, main);
