// Lighthouse and axe-core on the built page, served as a class gets it (scripts/web.sh
// --no-build: caddy with web/serve/Caddyfile, compressed copies and cache headers):
// - Lighthouse 12 (npm `lighthouse`, in Debian's Chromium started by chrome-launcher) in its
//   mobile and its desktop preset: a first visit, so the welcome shows;
// - axe-core (npm `axe-core`, injected into the page) at a phone (390x844, touch) and a laptop
//   (1366x768), each as a first visit (the welcome) and as a returning student (the panels).
// Writes every score and figure to build/web-test/audit.json (Lighthouse's own reports beside
// it: lighthouse-mobile.html, ...) and prints a table. Fails on an axe violation that
// tests/web/audit_allowed.json does not list with its reason, and on Lighthouse accessibility or
// best-practices below 100. Performance and SEO are reported, not judged: they measure this
// machine's load as much as the page (bench/RESULTS.md, "A school day").
// What they cannot see: everything the app draws in its canvas. They judge the parallel DOM
// (web/parallel_dom.js), the hidden elements that mirror each item drawn, not the pixels.
//   node tests/web/audit.mjs   (scripts/audit.sh builds and installs first)
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

const CATEGORIES = ['performance', 'accessibility', 'best-practices', 'seo'];
const JUDGED = ['accessibility', 'best-practices'];
// The page as the harness's Chromium runs it (harness.mjs, launchBrowser), in the new headless.
const CHROME_FLAGS = ['--headless=new', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
                      '--disable-background-networking', '--disable-component-update', '--disable-sync',
                      '--use-angle=swiftshader', '--enable-unsafe-swiftshader'];
// How long Lighthouse waits for the page to fall quiet (its default 45 s). A page that never
// idles uses all of it; the time to interactive it reports is then cut at this wait.
const MAX_WAIT_FOR_LOAD_MS = 45_000;
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
                                           onlyCategories: CATEGORIES, maxWaitForLoad: MAX_WAIT_FOR_LOAD_MS },
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

// axe-core's violations on one page: by rule, with its impact and the elements (CSS selectors).
async function axeRun(url, size, visit) {
  await launchBrowser(SIZES[size]);
  const label = `${size}, ${visit}`;
  const { page, started, error } = await openApp(visit === 'welcome' ? url + '?welcome' : url, `axe ${label}`);
  try {
    if (!check(`axe ${label}: the app starts`, started, error || '')) return null;
    if (visit === 'welcome')
      check(`axe ${label}: the welcome shows`, await page.evaluate(() => window.swarmlab.welcomeShown()));
    await page.addScriptTag({ path: axePath });
    return await page.evaluate(async () => {
      const r = await window.axe.run(document, { resultTypes: ['violations'] });
      return {
        axeVersion: r.testEngine.version, passes: r.passes.length, incomplete: r.incomplete.map((i) => i.id),
        violations: Object.fromEntries(r.violations.map((v) => [v.id, {
          impact: v.impact, help: v.help, nodes: v.nodes.length,
          targets: v.nodes.slice(0, 5).map((n) => n.target.join(' ') + (n.html ? ` ${n.html.slice(0, 120)}` : '')),
        }])),
      };
    });
  } finally {
    await closeBrowser();
  }
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
  const report = { date: new Date().toISOString(), commit: commit(), url, load: { start: load() }, lighthouse: {}, axe: {}, allowed };

  for (const preset of ['mobile', 'desktop']) {
    const f = report.lighthouse[preset] = lighthouseFigures(await lighthouseRun(url, preset));
    check(`lighthouse ${preset}: the page loads`, !f.runtimeError, f.runtimeError || '');
    for (const category of JUDGED)
      check(`lighthouse ${preset}: ${category} 100`, f.scores[category] === 100,
            `${f.scores[category]}: ` + f.failing[category].map((a) => `${a.id} (${a.title}${a.items.length ? ': ' + a.items.join(', ') : ''})`).join('; '));
  }

  for (const size of Object.keys(SIZES))
    for (const visit of ['welcome', 'returning']) {
      const where = `${size}, ${visit}`;
      const result = report.axe[where] = await axeRun(url, size, visit);
      if (!result) continue;
      const unreviewed = Object.entries(result.violations).filter(([id]) =>
        !allowed.some((a) => a.rule === id && (!a.where || a.where === where)));
      check(`axe ${where}: no violation outside tests/web/audit_allowed.json`, unreviewed.length === 0,
            unreviewed.map(([id, v]) => `${id} (${v.impact}: ${v.help}; ${v.nodes} elements: ${v.targets.join(' | ')})`).join('; '));
    }
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

// Two Lighthouse runs that wait up to 45 s each for a page that never idles, and four pages.
runSuite('audit', 280_000, main, { serve: startWebServer });
