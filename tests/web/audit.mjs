// Lighthouse and axe-core on the built page, served as a class gets it (scripts/web.sh
// --no-build: caddy with web/serve/Caddyfile, compressed copies and cache headers):
// - Lighthouse 12 (npm `lighthouse`, in Debian's Chromium started by chrome-launcher) in its
//   mobile and its desktop preset: a first visit, so the welcome shows;
// - axe-core (npm `axe-core`, injected into the page) at a phone (390x844, touch) and a laptop
//   (1366x768), each on a first visit (the welcome) and once the person has closed the welcome
//   (the panels a returning student sees).
// Writes every score and figure to build/web-test/audit.json (Lighthouse's own reports beside
// it: lighthouse-mobile.html, ...) and prints a table. Fails on an axe violation that
// tests/web/audit_allowed.json does not list with its reason, and on Lighthouse accessibility or
// best-practices below 100. Performance and SEO are reported, not judged: they measure this
// machine's load as much as the page (bench/RESULTS.md, "A school day").
// What they cannot see: everything the app draws in its canvas. They judge the parallel DOM
// (web/parallel_dom.js), the hidden elements that mirror each item drawn, not the pixels.
//   node tests/web/audit.mjs [--lighthouse-wait MS]   (scripts/audit.sh builds and installs first)
import lighthouse from 'lighthouse';
import desktopConfig from 'lighthouse/core/config/desktop-config.js';
import { launch } from 'chrome-launcher';
import { createRequire } from 'node:module';
import { execSync } from 'node:child_process';
import { readFileSync, writeFileSync } from 'node:fs';
import { loadavg } from 'node:os';
import { join } from 'node:path';
import { root, outDir, chromiumPath, check, runSuite, startWebServer, launchBrowser, closeBrowser, openApp,
         pageErrors, consoleErrors } from './harness.mjs';
import { person } from './person.mjs';

const CATEGORIES = ['performance', 'accessibility', 'best-practices', 'seo'];
const JUDGED = ['accessibility', 'best-practices'];
// The page as the harness's Chromium runs it (harness.mjs, launchBrowser), in the new headless.
const CHROME_FLAGS = ['--headless=new', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
                      '--disable-background-networking', '--disable-component-update', '--disable-sync',
                      '--use-angle=swiftshader', '--enable-unsafe-swiftshader'];
// How long Lighthouse waits for the page to fall quiet (its default is 45 s): a page that never
// idles waits all of it, and the time to interactive and total blocking time it reports then
// count what happened within it. 10 s keeps the audit short; the figures in bench/RESULTS.md
// ("A school day") were taken with Lighthouse's own 45 s (--lighthouse-wait 45000).
const waitAt = process.argv.indexOf('--lighthouse-wait');
const MAX_WAIT_FOR_LOAD_MS = waitAt > 0 ? Number(process.argv[waitAt + 1]) : 10_000;
const SIZES = { phone: { width: 390, height: 844, hasTouch: true, isMobile: true }, laptop: { width: 1366, height: 768 } };
const axePath = createRequire(import.meta.url).resolve('axe-core/axe.min.js');
const allowedFile = join(root, 'tests/web/audit_allowed.json');

const load = () => loadavg().map((x) => +x.toFixed(2));
const commit = () => {
  try { return execSync('git rev-parse --short HEAD', { cwd: root, encoding: 'utf8' }).trim() +
               (execSync('git status --porcelain --untracked-files=no', { cwd: root, encoding: 'utf8' }).trim() ? ' (with changes)' : ''); }
  catch { return 'unknown'; }
};

// The reviewed exceptions: [{ rule, where?, reason }]; `where` (e.g. "phone, welcome") limits
// one to an audit; every entry needs its reason.
function allowList() {
  const list = JSON.parse(readFileSync(allowedFile, 'utf8')).allowed;
  for (const entry of list)
    if (!entry.rule || !entry.reason || !entry.reason.trim()) throw new Error(`${allowedFile}: an entry without its rule or reason: ${JSON.stringify(entry)}`);
  return list;
}

// A run of Lighthouse in a Chromium of its own; `preset` 'mobile' (its default config) or 'desktop'.
let chrome = null;
process.on('exit', () => { if (chrome) try { process.kill(chrome.pid, 'SIGKILL'); } catch { /* gone */ } });
async function lighthouseRun(url, preset) {
  chrome = await launch({ chromePath: chromiumPath, chromeFlags: CHROME_FLAGS });
  const t0 = Date.now();
  try {
    const result = await lighthouse(url, { port: chrome.port, output: ['json', 'html'], logLevel: 'error',
                                           onlyCategories: CATEGORIES, maxWaitForLoad: MAX_WAIT_FOR_LOAD_MS,
                                           // What costs time and no score: the full-page screenshot,
                                           // the back/forward cache's extra navigation, the filmstrip.
                                           disableFullPageScreenshot: true,
                                           skipAudits: ['bf-cache', 'screenshot-thumbnails', 'final-screenshot'] },
                                     preset === 'desktop' ? desktopConfig : undefined);
    writeFileSync(join(outDir, `lighthouse-${preset}.json`), result.report[0]);
    writeFileSync(join(outDir, `lighthouse-${preset}.html`), result.report[1]);
    return { lhr: result.lhr, seconds: (Date.now() - t0) / 1000 };
  } finally {
    await chrome.kill();
    chrome = null;
  }
}

// What a Lighthouse report says, in short: the scores (0-100), the load figures (ms), and each
// category's audits that did not pass, with the elements they name.
function lighthouseFigures({ lhr, seconds }) {
  const ms = (id) => (lhr.audits[id]?.numericValue == null ? null : Math.round(lhr.audits[id].numericValue));
  const failing = {};
  for (const category of CATEGORIES) {
    failing[category] = (lhr.categories[category]?.auditRefs || [])
      .filter((ref) => ref.weight > 0 && lhr.audits[ref.id].score !== null && lhr.audits[ref.id].score < 1)
      .map((ref) => {
        const audit = lhr.audits[ref.id];
        const items = (audit.details?.items || []).slice(0, 5)
          .map((item) => item.node?.selector || item.node?.snippet || item.description || item.url || item.source?.url || '')
          .filter(Boolean);
        return { id: ref.id, title: audit.title, score: audit.score, displayValue: audit.displayValue, items };
      });
  }
  return {
    scores: Object.fromEntries(CATEGORIES.map((c) => [c, lhr.categories[c]?.score == null ? null : Math.round(100 * lhr.categories[c].score)])),
    totalBlockingTimeMs: ms('total-blocking-time'), timeToInteractiveMs: ms('interactive'),
    largestContentfulPaintMs: ms('largest-contentful-paint'), firstContentfulPaintMs: ms('first-contentful-paint'),
    failing, runtimeError: lhr.runtimeError?.message || null, runWarnings: lhr.runWarnings,
    lighthouseVersion: lhr.lighthouseVersion, userAgent: lhr.environment?.hostUserAgent,
    benchmarkIndex: lhr.environment?.benchmarkIndex, seconds,
  };
}

// axe-core's violations on the page as it is: by rule, with its impact and the elements (CSS
// selectors).
async function axeRun(page) {
  // Evaluated, not added as a <script>: the page's CSP runs no inline script but its own.
  await page.evaluate(readFileSync(axePath, 'utf8'));
  return page.evaluate(async () => {
    const r = await window.axe.run(document, { resultTypes: ['violations'] });
    return {
      axeVersion: r.testEngine.version, passes: r.passes.length, incomplete: r.incomplete.map((i) => i.id),
      violations: Object.fromEntries(r.violations.map((v) => [v.id, {
        impact: v.impact, help: v.help, nodes: v.nodes.length,
        targets: v.nodes.slice(0, 5).map((n) => n.target.join(' ') + (n.html ? ` ${n.html.slice(0, 120)}` : '')),
      }])),
    };
  });
}

// At one size: a first visit (the welcome), then, after the person closes the welcome as a
// person does (Just the simulation, by finger on the phone, by mouse on the laptop), the
// panels a returning student sees; on the laptop also the View menu open and the method
// combo's list open. Judges each against the allow-list.
async function axeAt(url, size, report, allowed) {
  await launchBrowser(SIZES[size]);
  try {
    const { page, started, error } = await openApp(url + '?welcome', `axe ${size}`);
    if (!check(`axe ${size}: the app starts`, started, error || '')) return;
    check(`axe ${size}: a first visit shows the welcome`, await page.evaluate(() => window.swarmlab.welcomeShown()));
    judge(`${size}, welcome`, report.axe[`${size}, welcome`] = await axeRun(page), allowed);
    await person(page, SIZES[size].hasTouch ? 'touch' : 'mouse').press('button', 'Just the simulation');
    await page.waitForFunction(() => !window.swarmlab.welcomeShown());
    judge(`${size}, panels`, report.axe[`${size}, panels`] = await axeRun(page), allowed);
    if (size !== 'laptop') return;
    // An open menu and an open combo's list: their entries nest in what opened them.
    const me = person(page, 'mouse');
    await me.press('menuitem', 'View');
    await page.waitForSelector('#parallel-dom [role="menu"] [role^="menuitem"]', { state: 'attached' });
    judge(`${size}, menu open`, report.axe[`${size}, menu open`] = await axeRun(page), allowed);
    await me.press('menuitem', 'View');  // closes it again
    await page.waitForSelector('#parallel-dom [role="menu"]', { state: 'detached' });
    await me.press('combobox', 'method');
    await page.waitForSelector('#parallel-dom [role="combobox"] + [role="listbox"] [role="option"]', { state: 'attached' });
    judge(`${size}, list open`, report.axe[`${size}, list open`] = await axeRun(page), allowed);
  } finally {
    await closeBrowser();
  }
}

function judge(where, result, allowed) {
  const unreviewed = Object.entries(result.violations).filter(([id]) =>
    !allowed.some((a) => a.rule === id && (!a.where || a.where === where)));
  check(`axe ${where}: no violation outside tests/web/audit_allowed.json`, unreviewed.length === 0,
        unreviewed.map(([id, v]) => `${id} (${v.impact}: ${v.help}; ${v.nodes} elements: ${v.targets.join(' | ')})`).join('; '));
}

function table(report) {
  const cell = (v, w) => String(v ?? '-').padStart(w);
  const lines = ['', 'audit                  perf  a11y  best   seo    TBT ms    TTI ms    LCP ms'];
  for (const [preset, f] of Object.entries(report.lighthouse))
    lines.push(`lighthouse ${preset.padEnd(11)} ${cell(f.scores.performance, 4)}  ${cell(f.scores.accessibility, 4)}  ` +
               `${cell(f.scores['best-practices'], 4)}  ${cell(f.scores.seo, 4)}  ${cell(f.totalBlockingTimeMs, 8)}  ` +
               `${cell(f.timeToInteractiveMs, 8)}  ${cell(f.largestContentfulPaintMs, 8)}   (${f.seconds.toFixed(0)} s)`);
  for (const [where, a] of Object.entries(report.axe)) {
    const ids = a ? Object.entries(a.violations).map(([id, v]) => `${id} (${v.impact}, ${v.nodes})`) : ['did not run'];
    lines.push(`axe ${where.padEnd(18)} ${ids.length ? ids.join(', ') : `no violations (${a.passes} rules pass)`}`);
  }
  lines.push(`load average ${report.load.start.join(' ')} at the start, ${report.load.end.join(' ')} at the end; ` +
             `${report.seconds.toFixed(0)} s; build/web-test/audit.json`, '');
  return lines.join('\n');
}

async function main(url) {
  const t0 = Date.now();
  const allowed = allowList();
  const report = { date: new Date().toISOString(), commit: commit(), url, lighthouseWaitMs: MAX_WAIT_FOR_LOAD_MS,
                   load: { start: load() }, lighthouse: {}, axe: {}, allowed };

  for (const preset of ['mobile', 'desktop']) {
    const f = report.lighthouse[preset] = lighthouseFigures(await lighthouseRun(url, preset));
    check(`lighthouse ${preset}: the page loads`, !f.runtimeError, f.runtimeError || '');
    for (const category of JUDGED)
      check(`lighthouse ${preset}: ${category} 100`, f.scores[category] === 100,
            `${f.scores[category]}: ` + f.failing[category].map((a) => `${a.id} (${a.title}${a.items.length ? ': ' + a.items.join(', ') : ''})`).join('; '));
  }

  for (const size of Object.keys(SIZES)) await axeAt(url, size, report, allowed);
  const used = new Set(Object.entries(report.axe).flatMap(([where, a]) => (a ? Object.keys(a.violations).map((id) => `${id}@${where}`) : [])));
  for (const a of allowed)
    if (![...used].some((u) => u.startsWith(a.rule + '@') && (!a.where || u.endsWith('@' + a.where))))
      console.log(`note: tests/web/audit_allowed.json allows ${a.rule}${a.where ? ' at ' + a.where : ''}, which no audit found: remove it?`);

  check('the pages threw no errors and logged none', pageErrors.length === 0 && consoleErrors.length === 0,
        [...pageErrors, ...consoleErrors].slice(0, 5).join(' | '));
  report.load.end = load();
  report.seconds = (Date.now() - t0) / 1000;
  writeFileSync(join(outDir, 'audit.json'), JSON.stringify(report, null, 2) + '\n');
  console.log(table(report));
}

// Two Lighthouse runs that wait for a page that never idles, and two pages.
runSuite('audit', 250_000 + 2 * MAX_WAIT_FOR_LOAD_MS, main, { serve: startWebServer });
