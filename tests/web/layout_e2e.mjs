// Layouts survive translation (issue: "a pseudo-language exists for tests only, and at the six
// viewports in both themes no item's text is cut off or overlaps another"). In the
// pseudo-language (#lang=x-pseudo: every text accented and about 1.6x longer, app/i18n), at the
// six classroom screen sizes, in the dark and the light theme (set as a person sets it: View >
// Light theme), with the main panels showing and on a phone each of the drawer's tabs opened
// as a person opens them: no mirrored item is cut off (the parallel DOM's data-cut: its label
// wider than the room it is drawn in, or the item sticking out of its window sideways), no
// plain text is cut off (the parallel DOM's cut_text), and no two items of one window overlap.
// A screenshot of each size and theme goes to build/web-test/layout/.
// Run through tests/web/run.sh; the last line is "N passed, M failed".
import * as harness from './harness.mjs';
import { person } from './person.mjs';

import { mkdirSync } from 'node:fs';
import { join } from 'node:path';

const { check, openApp, launchBrowser, runSuite, outDir, pageErrors, consoleErrors, until } = harness;

const shotDir = join(outDir, 'layout');
// LAYOUT_LANG=de (fr, zh-CN...) looks at a real language instead, in the dark theme (the View
// menu's name is the pseudo-language's); LAYOUT_SIZES='[[390,844]]' at fewer sizes.
const LANG = process.env.LAYOUT_LANG || 'x-pseudo';
const SIZES = process.env.LAYOUT_SIZES ? JSON.parse(process.env.LAYOUT_SIZES) : [[390, 844], [844, 390], [1024, 768], [1366, 768], [1280, 720], [1920, 1080]];

const appState = (page) => page.evaluate(() => window.swarmlab.state());
// The text the page shows for an English one in its language (web/page_text.js's pageText,
// which in the pseudo-language is swarmlab::pseudo_text's), as the parallel DOM names it
// (trimmed): the app's menus must carry the same names for the finds below to succeed.
const shown = (page, english) => page.evaluate((e) => window.pageText(e).trim(), english);

// The app has laid the canvas out at W x H, the layout holds, and the page's mirror has
// followed two frames drawn since, or the loop sleeps (the items' rectangles are the settled ones).
async function settled(page, W, H) {
  const s = await until(page, (st, a) => st.display.width === a.W && st.display.height === a.H && st.layout_settled, { W, H });
  const f = await page.evaluate(() => window.swarmlab.frames());
  await page.waitForFunction((t) => window.swarmlab.frames() >= t || window.swarmlab.sleeping(), f + 2, { timeout: 20_000 }).catch(() => {});
  return s;
}

const rectText = (r) => `${Math.round(r.x)},${Math.round(r.y)} ${Math.round(r.width)}x${Math.round(r.height)}`;

// What the mirror says of the frame: the items (region, role, name, rect, cut) and the plain
// text that was cut off.
const mirrored = (page) => page.evaluate(() => {
  const items = [...document.querySelectorAll('#parallel-dom .pdom-item')].map((e) => {
    const r = e.getBoundingClientRect();
    return { region: e.closest('.pdom-region')?.getAttribute('aria-label') || '', tag: e.tagName,
             role: e.getAttribute('role') || (e.tagName === 'BUTTON' ? 'button' : e.tagName === 'INPUT' ? 'textbox' : e.tagName),
             name: e.getAttribute('aria-label') || e.textContent, x: r.x, y: r.y, width: r.width, height: r.height,
             clipped: e.dataset.clipped === 'true', cut: e.dataset.cut === 'true' };
  });
  return { items, cutText: Module.swarmlabCutText || [] };
});

// Two rectangles overlapping by more than 1 px both ways, neither holding the other (a
// section's header holds nothing; a plot's area may hold its own buttons).
const overlapPx = (a, b) => Math.min(Math.min(a.x + a.width, b.x + b.width) - Math.max(a.x, b.x),
                                     Math.min(a.y + a.height, b.y + b.height) - Math.max(a.y, b.y));
const holds = (a, b) => a.x <= b.x + 0.5 && a.y <= b.y + 0.5 && a.x + a.width >= b.x + b.width - 0.5 &&
                        a.y + a.height >= b.y + b.height - 0.5;

function problems(frame, where) {
  const out = [];
  for (const it of frame.items)
    if (it.cut && !it.clipped) out.push(`${where}: cut off: ${it.role} "${it.name}" in "${it.region}" at ${rectText(it)}`);
  for (const t of frame.cutText)
    out.push(`${where}: text cut off: "${t.name}" in "${t.region}" needs ${rectText(t)}`);
  // Items (not text: a paragraph's mirror spans to its window's edge) of one window.
  const boxes = frame.items.filter((it) => !it.clipped && it.tag !== 'P' && it.tag !== 'H2');
  for (let i = 0; i < boxes.length; ++i)
    for (let j = i + 1; j < boxes.length; ++j) {
      const a = boxes[i], b = boxes[j];
      if (a.region !== b.region || overlapPx(a, b) <= 1 || holds(a, b) || holds(b, a)) continue;
      out.push(`${where}: overlap in "${a.region}": ${a.role} "${a.name}" ${rectText(a)} / ${b.role} "${b.name}" ${rectText(b)}`);
    }
  return out;
}

// Whether the drawer's tab `name` is the one open (its mirrored element says so).
const isSelected = (n) => [...document.querySelectorAll('#parallel-dom [role=tab]')]
  .some((e) => e.textContent === n && e.getAttribute('aria-selected') === 'true');
const selected = (page, name) => page.evaluate(isSelected, name);

// Each panel scrolled through from top to bottom as a person does it, with the wheel over it:
// what is out of sight is not drawn, so it is looked at where it shows.
async function scrolledThrough(page, W, H, where) {
  const found = [];
  const panel = (st, name) => st.panels.find((p) => p.name === name);
  for (const { name } of (await appState(page)).panels) {
    // A turn of the wheel scrolls ImGui a fixed step: as many as make most of a panel's height.
    let notchPx = 0;
    for (let steps = 0; steps < 40; ++steps) {
      const p = panel(await appState(page), name);
      if (!p || p.scroll >= p.scroll_max - 1) break;
      await page.mouse.move(p.x + p.width / 2, p.y + p.height / 2);
      const notches = notchPx > 0 ? Math.max(1, Math.floor((0.8 * p.height) / notchPx)) : 1;
      for (let i = 0; i < notches; ++i) await page.mouse.wheel(0, 100);
      const after = panel(await until(page, (st, a) => st.panels.some((q) => q.name === a.name && q.scroll !== a.scroll),
                                      { name, scroll: p.scroll }), name);
      if (!notchPx && after) notchPx = after.scroll - p.scroll;
      await settled(page, W, H);
      found.push(...problems(await mirrored(page), `${where}, ${name} scrolled down`));
    }
  }
  return found;
}

async function checkSize(page, who, W, H, theme) {
  await page.setViewportSize({ width: W, height: H });
  let s = await settled(page, W, H);
  const label = `${W}x${H} ${theme}`;
  const found = [];
  if (s.layout === 'wide') {
    found.push(...problems(await mirrored(page), label));
    found.push(...await scrolledThrough(page, W, H, label));
  } else {
    // Compact: the drawer's tabs, each opened as a person opens it.
    const tabs = (await mirrored(page)).items.filter((it) => it.role === 'tab');
    for (const { name } of tabs) {
      // A click the tab bar missed (seen now and then on a loaded machine) is clicked again,
      // as a person would.
      for (let tries = 0; tries < 3 && !(await selected(page, name)); ++tries) {
        await who.press('tab', name);
        await page.waitForFunction(isSelected, name, { timeout: 5_000 }).catch(() => {});
      }
      if (!(await selected(page, name))) { found.push(`${label}: the tab "${name}" would not open`); continue; }
      s = await settled(page, W, H);
      found.push(...problems(await mirrored(page), `${label} tab "${name}"`));
      found.push(...await scrolledThrough(page, W, H, `${label} tab "${name}"`));
    }
  }
  // The pointer off the panels (over the view), so that no tooltip covers them.
  await page.mouse.move(s.view.x + s.view.width / 2, s.view.y + s.view.height / 2);
  await settled(page, W, H);
  const file = `layout-${LANG === 'x-pseudo' ? '' : LANG + '-'}${W}x${H}-${theme}.png`;
  await page.screenshot({ path: join(shotDir, file) });
  console.log(`      screenshot -> build/web-test/layout/${file}`);
  // One line per item (an item cut off at several scroll positions is reported where first seen).
  const seen = new Set();
  const once = found.filter((f) => { const key = f.replace(/^[^:]*: /, '').replace(/ at \d.*$/, ''); return !seen.has(key) && seen.add(key); });
  check(`${label} (${s.layout}): nothing cut off, nothing overlapping`, once.length === 0,
        once.length ? '\n        ' + once.join('\n        ') : '');
}

async function main(url) {
  mkdirSync(shotDir, { recursive: true });
  await launchBrowser({ width: 1280, height: 720 });
  const { page, started, error } = await openApp(`${url}#lang=${LANG}`, 'layout');
  if (!check(`the app starts in ${LANG}`, started, error || '')) return;
  if (LANG !== 'x-pseudo') {
    for (const [W, H] of SIZES) await checkSize(page, person(page, 'mouse'), W, H, 'dark');
    return;
  }
  const who = person(page, 'mouse');
  const view = await shown(page, 'View'), lightTheme = await shown(page, 'Light theme');
  await page.waitForFunction((n) => !!document.querySelector(`#parallel-dom [aria-label="${n}"]`) ||
                             [...document.querySelectorAll('#parallel-dom button')].some((e) => e.textContent === n),
                             view, { timeout: 20_000 }).catch(() => {});
  check('the menus are in the pseudo-language', view !== 'View' && await who.find('menuitem', view).count() === 1, view);

  for (const theme of ['dark', 'light']) {
    if (theme === 'light') {
      await page.setViewportSize({ width: 1280, height: 720 });
      await settled(page, 1280, 720);
      await who.press('menuitem', view);
      await who.press('menuitem', lightTheme);
      const s = await until(page, (st) => st.theme === 'light');
      if (!check('View > Light theme sets the light theme', s.theme === 'light', s.theme)) return;
    }
    for (const [W, H] of SIZES) await checkSize(page, who, W, H, theme);
  }
  check('no page errors', pageErrors.length === 0, pageErrors.join(' | '));
  check('no console errors', consoleErrors.length === 0, consoleErrors.join(' | '));
}

runSuite('layout_e2e', 150_000, main);
