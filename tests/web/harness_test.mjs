// The suites' watchdog (harness.mjs, runSuite) measures a stall, not the whole run: a suite that
// keeps making checks passes however long it runs in all, and a suite that stops making checks
// fails within its stall limit, saying so. Each case is a child process (runSuite ends its
// process) with no browser and no server.
import { spawnSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';

const harness = new URL('./harness.mjs', import.meta.url).href;
// A suite with a stall limit of 1.5 s whose checks come every `everyMs` until `totalMs` have passed.
function suite(everyMs, totalMs) {
  const body = `
    import { runSuite, check, sleep } from '${harness}';
    runSuite('watchdog-case', 1500, async () => {
      const start = Date.now();
      while (Date.now() - start < ${totalMs}) { await sleep(${everyMs}); check('a step', true); }
    }, { serve: async () => 'http://127.0.0.1:9/' });`;
  const t0 = Date.now();
  const r = spawnSync(process.execPath, ['--input-type=module', '-e', body], { encoding: 'utf8', timeout: 30_000 });
  return { status: r.status, out: r.stdout + r.stderr, seconds: (Date.now() - t0) / 1000 };
}

let failures = 0;
function expect(name, ok, detail) {
  console.log(`${ok ? 'ok  ' : 'FAIL'}  ${name} (${detail})`);
  if (!ok) failures++;
}
// Four seconds in all, a check every 0.3 s: more than the limit in all, never a stall.
const steady = suite(300, 4000);
expect('a suite that keeps making checks runs past its limit and passes', steady.status === 0 && /0 failed/.test(steady.out),
       `exit ${steady.status}, ${steady.seconds.toFixed(1)} s`);
// A check, then 6 s of nothing: the watchdog ends it after about 1.5 s of silence.
const stuck = suite(6000, 1);
expect('a suite that stops making checks fails within its stall limit, saying so',
       stuck.status === 1 && /a check is made at least every 1\.5 s/.test(stuck.out) && stuck.seconds < 5.5,
       `exit ${stuck.status}, ${stuck.seconds.toFixed(1)} s`);
process.exit(failures ? 1 : 0);
