// Browser checks of time travel (issue 13): swarmlab.seek(t) back and forth lands on the same
// positions() to the last digit, with a container too; on the isolated Fig. 1 preset a seek
// gives the analytic solution (computed here, independently) and the positions of a fresh run
// taken to the same time; state().t_reached; the End key fast-forwards with progress shown
// in state().fast_forward, and finishes at the run's end. Frames are counted, not
// milliseconds: the machine may be loaded.
import { join } from 'node:path';
import * as harness from './harness.mjs';

const { check, shipped, openApp, launchBrowser, runSuite, pageErrors, consoleErrors } = harness;

async function main(url) {
  await launchBrowser({ width: 1280, height: 720 });
  const { page, started, error } = await openApp(url, 'time');
  if (!check('the app starts', started, error || '')) return;
  const api = (fn, ...args) => page.evaluate(fn, ...args);
  const framesPass = async (n) => {
    const start = await api(() => window.swarmlab.frames());
    await page.waitForFunction((t) => window.swarmlab.frames() >= t, start + n, { timeout: 30_000 });
  };
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

  // 3. Fast-forward to the end of the run: End, progress, the end.
  const ff = { ...shipped('fig2-attractive-expansion.json'), name: 'time test expansion' };
  ff.expansion = { ...ff.expansion, stages: 4, tau: 60 };
  await api((p) => window.swarmlab.load(p), ff);
  await page.mouse.click(620, 300);  // focus the canvas
  await page.keyboard.down('End');
  await framesPass(2);
  await page.keyboard.up('End');
  let sawProgress = null, endState = null;
  for (let i = 0; i < 2000; i++) {
    const st = await api(() => window.swarmlab.state());
    if (st.fast_forward && st.fast_forward.progress > 0 && st.fast_forward.progress < 1 && sawProgress === null) {
      sawProgress = st.fast_forward.progress;
      await page.screenshot({ path: join(harness.outDir, 'time-fast-forward.png') });
    }
    if (!st.fast_forward && st.t > 0) { endState = st; break; }
    await framesPass(1);
  }
  check('End fast-forwards with its progress shown', sawProgress !== null, `progress seen ${sawProgress}`);
  check('the fast-forward finishes at the end of the run', endState && Math.abs(endState.t - 240) < 1e-6 && Math.abs(endState.t_reached - 240) < 1e-6,
        endState ? `t = ${endState.t}` : 'did not finish');
  await framesPass(3);
  check('the window kept drawing', true);

  check('no page errors', pageErrors.length === 0, pageErrors.join(' | '));
  check('no console errors', consoleErrors.length === 0, consoleErrors.join(' | '));
}

runSuite('time_e2e', 140_000, main);
