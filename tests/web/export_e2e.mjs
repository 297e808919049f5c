// Browser tests of export and of labels that stay true (issue 13): swarmlab.exportCsv()
// downloads the samples with the columns of `swarmlab run --csv`; a preset opened from a link
// is "edited" unless it is a shipped one as shipped; leaving the page asks only after an edit;
// a plot's exports say what made them.
import { spawnSync } from 'node:child_process';
import { existsSync, readFileSync, writeFileSync, mkdtempSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import * as harness from './harness.mjs';
import { person } from './person.mjs';

const { check, openApp, launchBrowser, runSuite, base64url, shipped, pageErrors, consoleErrors,
        cliPath } = harness;

// The header line `swarmlab run --csv` writes for the preset (null when the CLI is not built).
function cliCsvHeader(presetJson) {
  if (!existsSync(cliPath)) return null;
  const dir = mkdtempSync(join(tmpdir(), 'swarmlab-export-'));
  writeFileSync(join(dir, 'p.json'), presetJson);
  const r = spawnSync(cliPath, ['run', join(dir, 'p.json'), '--csv', join(dir, 'p.csv'), '--quiet'],
                      { encoding: 'utf8', timeout: 60_000 });
  if (r.status !== 0) return null;
  return readFileSync(join(dir, 'p.csv'), 'utf8').split('\n')[0];
}

// The fields of a CSV row of numbers, each in quotes as every field is (app/report/csv_field.h).
const fields = (line) => line.split(',').map((f) => f.replace(/^"(.*)"$/, '$1'));

// Whether the page's beforeunload handler would ask (it cancels the event only with edits).
const beforeUnloadArmed = (page) => page.evaluate(() => {
  const e = new Event('beforeunload', { cancelable: true });
  window.dispatchEvent(e);
  return e.defaultPrevented;
});

async function main(url) {
  await launchBrowser();
  const { page, started, error } = await openApp(url, 'export');
  if (!check('the app starts', started, error || '')) return;
  const fig1 = shipped('fig1-four-masses.json');

  // 1. Nothing edited yet: not edited, leaving does not ask.
  let st = await page.evaluate(() => window.swarmlab.state());
  check('a shipped preset as opened is not edited', st.edited === false, JSON.stringify(st));
  check('beforeunload is not armed before an edit', (await beforeUnloadArmed(page)) === false);

  // 2. A link to the shipped preset as shipped: still not edited.
  const plain = await page.evaluate((h) => window.swarmlab.openLink(h),
                                    '#preset=' + base64url(Buffer.from(JSON.stringify(fig1))));
  st = await page.evaluate(() => window.swarmlab.state());
  check('a link to the shipped preset as shipped is not edited', plain === '' && st.edited === false,
        `error "${plain}", ${JSON.stringify(st)}`);

  // 3. A link that carries the shipped name with another J: edited, and leaving asks.
  const changed = { ...fig1, J: -0.5 };
  const err = await page.evaluate((h) => window.swarmlab.openLink(h),
                                  '#preset=' + base64url(Buffer.from(JSON.stringify(changed))));
  st = await page.evaluate(() => window.swarmlab.state());
  check('a link-opened edited preset shows edited: true in state()', err === '' && st.edited === true &&
        st.name === fig1.name, `error "${err}", ${JSON.stringify(st)}`);
  check('beforeunload is armed after the edit', (await beforeUnloadArmed(page)) === true);

  // 4. exportCsv(): a download named as returned, with the CLI's header for the same preset.
  await page.waitForFunction(() => window.swarmlab.time() > 0.1, null, { timeout: 30_000 });
  const [download, name] = await Promise.all([
    page.waitForEvent('download', { timeout: 15_000 }).catch(() => null),
    page.evaluate(() => window.swarmlab.exportCsv())]);
  const text = download ? readFileSync(await download.path(), 'utf8') : '';
  const lines = text.split('\n').filter(Boolean);
  const running = await page.evaluate(() => window.swarmlab.preset());
  const header = cliCsvHeader(running);
  check('exportCsv() downloads a .csv named as it returns', download && name.endsWith('.csv') &&
        download.suggestedFilename() === name, `returned "${name}", downloaded "${download && download.suggestedFilename()}"`);
  check('the CSV header equals `swarmlab run --csv` on the same preset',
        header !== null && lines[0] === header, `page "${lines[0]}", CLI "${header}"`);
  check('every CSV row has the header\'s columns, numbers only', lines.length >= 2 &&
        lines.slice(1).every((l) => l.split(',').length === lines[0].split(',').length && fields(l).every((f) => f !== '' && isFinite(Number(f)))),
        `${lines.length - 1} rows`);

  // 5. After a seek back the samples end at the time shown: the file says which range it holds,
  // and its last row is that time, not the furthest reached.
  const reached = (await page.evaluate(() => window.swarmlab.state())).t_reached;
  const shown = await page.evaluate((t) => window.swarmlab.seek(t), reached / 2);
  const [back, backName] = await Promise.all([
    page.waitForEvent('download', { timeout: 15_000 }).catch(() => null),
    page.evaluate(() => window.swarmlab.exportCsv())]);
  const backRows = back ? readFileSync(await back.path(), 'utf8').split('\n').filter(Boolean) : [];
  const lastT = backRows.length > 1 ? Number(fields(backRows.at(-1))[0]) : NaN;
  check('after a seek back the CSV\'s name says it ends at the time shown',
        /-samples-t0-to-t[0-9.e+-]+\.csv$/.test(backName) && Math.abs(Number(/-to-t(.*)\.csv$/.exec(backName)[1]) - shown) <= 1e-3 * Math.max(1, shown),
        `reached ${reached}, shown ${shown}, file "${backName}"`);
  // Samples come every few steps: the last is at most one sampling interval before it (the
  // interval read off the rows themselves, so how far the run had got does not matter).
  const times = lines.slice(1).map((l) => Number(fields(l)[0]));
  const interval = Math.max(...times.slice(1).map((t, i) => t - times[i]));
  check('and its rows end at that time, not at the time reached',
        lastT <= shown * (1 + 1e-9) && shown - lastT <= interval * (1 + 1e-9),
        `last t ${lastT}, shown ${shown}, reached ${reached}, sampling interval ${interval}`);

  // 6. A plot's Export SVG, CSV and PNG, pressed as a person does: each file says what made it
  // (docs/command-line.md, "Provenance"): this build's version, Emscripten, the browser, now, the seeds (the
  // link's preset lists its particles: none).
  const me = person(page, 'mouse');
  // The version of the build that made the page (scripts/web.sh builds it in build-wasm/), as
  // its `swarmlab --version` prints it.
  const versionHeader = join(harness.root, 'build-wasm/app/generated/swarmlab_version.h');
  const version = existsSync(versionHeader) ? (/SWARMLAB_VERSION "(.*)"/.exec(readFileSync(versionHeader, 'utf8')) || [])[1] : '';
  const saved = async (label) => {
    const [d] = await Promise.all([page.waitForEvent('download', { timeout: 15_000 }).catch(() => null),
                                   me.press('button', label)]);
    return d ? readFileSync(await d.path()) : null;
  };
  // '' when the lines say what they must, else what is wrong.
  const madeBy = (lines) => {
    const field = (key) => (lines.find((l) => l.startsWith(key + ': ')) || '').slice(key.length + 2);
    const age = Math.abs(Date.now() - Date.parse(field('date')));
    if (!version || !(lines[0] || '').startsWith(`made by swarmlab ${version} from commit ${version.split('-dirty-')[0]} `)) return `first line "${lines[0]}", the page's build ${version}`;
    if (!field('compiler').startsWith('Emscripten ')) return `compiler "${field('compiler')}"`;
    if (field('host') !== 'browser wasm32') return `host "${field('host')}"`;
    if (!/^\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ$/.test(field('date')) || !(age < 600_000)) return `date "${field('date')}"`;
    if (field('seeds') !== 'none (the particles are listed)') return `seeds "${field('seeds')}"`;
    return '';
  };
  const svg = await saved('Export SVG');
  const parsed = svg && await page.evaluate((text) => {
    const doc = new DOMParser().parseFromString(text, 'image/svg+xml');
    const meta = doc.querySelector('svg > metadata');
    return { xml: !doc.querySelector('parsererror'), lines: meta ? meta.textContent.split('\n').filter(Boolean) : [] };
  }, svg.toString('utf8'));
  const svgProblem = parsed ? madeBy(parsed.lines) : 'no download';
  check('Export SVG: well-formed XML whose <metadata> says what made it', parsed && parsed.xml && svgProblem === '', svgProblem);
  const csv = await saved('Export CSV');
  const csvLines = csv ? csv.toString('utf8').split('\n').filter(Boolean) : [];
  const comments = csvLines.filter((l) => l.startsWith('# ')).map((l) => l.slice(2));
  const csvProblem = madeBy(comments);
  check('Export CSV: comment lines say what made it, then the panel,series,x,y table',
        csvProblem === '' && csvLines[comments.length].startsWith('"panel","series",') &&
        csvLines.slice(0, comments.length).every((l) => l.startsWith('# ')), csvProblem || csvLines[comments.length]);
  const png = await saved('Export PNG');
  let pngText = '';
  for (let at = 8; png && at + 8 <= png.length; at += 12 + png.readUInt32BE(at)) {
    const n = png.readUInt32BE(at);
    if (png.toString('latin1', at + 4, at + 8) !== 'iTXt') continue;
    const body = png.subarray(at + 8, at + 8 + n);
    const end = body.indexOf(0);
    if (body.toString('latin1', 0, end) === 'Comment') pngText = body.subarray(end + 5).toString('utf8');
  }
  const pngProblem = png ? madeBy(pngText.split('\n')) : 'no download';
  check('Export PNG: an iTXt Comment says what made it', png && png.subarray(1, 4).toString() === 'PNG' && pngProblem === '', pngProblem);

  check('no page errors', pageErrors.length === 0, pageErrors.join(' | '));
  check('no console errors', consoleErrors.length === 0, consoleErrors.join(' | '));
}

await runSuite('export_e2e', 120_000, main);
