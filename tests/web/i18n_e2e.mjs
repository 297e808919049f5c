// Every classroom (issue 24): the app and its lessons in six languages, as a class meets them.
// A link's #lang= starts the page and the app in that language; View > Language, pressed with
// the mouse through the parallel DOM, switches it and the choice is remembered for the next
// visit; a typed number accepts '.' and ',' and shows the language's decimal separator; the
// Chinese font is fetched only when Chinese is chosen, and its glyphs are drawn; Copy link
// carries the language, and beats a remembered choice; windows opened in one language (the
// Lesson progress notice, the panels) are named in the next. Then, per language, a lesson step at a
// laptop size and on a phone, and the welcome on a phone, saved to build/web-test/i18n/ to be
// looked at. Last, a browser set to a locale that only an alias of languages.json names.
// window.swarmlab is only read.
import { readFileSync, mkdirSync } from 'node:fs';
import { join } from 'node:path';
import * as harness from './harness.mjs';
import { person } from './person.mjs';

const { root, outDir, check, openApp, launchBrowser, closeBrowser, runSuite, pageErrors, shipped, base64url } = harness;

const table = (code) => JSON.parse(readFileSync(join(root, 'assets/i18n', `${code}.json`), 'utf8'));
// The languages of the View > Language menu (assets/i18n/languages.json), the texts' own first.
const ROWS = table('languages');
const LANGUAGES = ROWS.filter((l) => !l.pseudo).map((l) => l.code);
const SOURCE = LANGUAGES[0];
const NATIVE = Object.fromEntries(ROWS.map((l) => [l.code, l.native_name]));
// The text a language shows for an English one (the table's, else the English).
const words = (code, english) => (code === SOURCE ? english : table(code)[english] || english);
const firstLesson = JSON.parse(readFileSync(join(root, 'assets/lessons/01-one-period.json'), 'utf8'));

const language = (page) => page.evaluate(() => window.swarmlab.state().language);
const until = (page, code) => page.waitForFunction((c) => window.swarmlab.state().language === c, code,
                                                    { timeout: 30_000 }).then(() => true, () => false);

// A number field's text as the page mirrors it.
const fieldText = (me, name) => me.find('textbox', name).evaluate((e) => e.value);

async function chooseLanguage(me, page, from, to) {
  await me.press('menuitem', words(from, 'View'));
  await me.press('menuitem', words(from, 'Language'));
  await me.press('menuitem', NATIVE[to]);
  return until(page, to);
}

async function main(url) {
  mkdirSync(join(outDir, 'i18n'), { recursive: true });
  await launchBrowser({ width: 1280, height: 720 });

  // 1. A Spanish link to a gas at a hot wall: the page and the app speak Spanish.
  const gas = base64url(Buffer.from(JSON.stringify(shipped('hot-wall.json'))));
  let { page, started, error } = await openApp(url + '#lang=es&preset=' + gas, 'i18n-es');
  if (!check('the app starts from a #lang=es link', started, error || '')) return;
  const me = person(page, 'mouse');
  check('#lang=es: the app speaks Spanish', await until(page, 'es'), await language(page));
  check('the page is marked Spanish for screen readers', await page.evaluate(() => document.documentElement.lang) === 'es');
  await me.find('menuitem', words('es', 'View')).waitFor({ state: 'attached', timeout: 30_000 });
  check('the menus are named in Spanish (Escenario, Vista, Lecciones, Ayuda)',
        (await Promise.all(['Scenario', 'View', 'Lessons', 'Help'].map((m) => me.find('menuitem', words('es', m)).count())))
          .every((n) => n === 1));

  // 2. View > Language > Deutsch, with the mouse: German at once, the menus renamed.
  check('View > Language > Deutsch switches to German', await chooseLanguage(me, page, 'es', 'de'), await language(page));
  await me.find('menuitem', words('de', 'View')).waitFor({ state: 'attached', timeout: 30_000 });
  check('the menus are renamed in German', await me.find('menuitem', 'Ansicht').count() === 1);

  // 3. Numbers: a typed '0,5' and '0.25' both read, and show with the decimal comma.
  const averageOver = words('de', 'average over');
  await me.press('tab', new RegExp('^' + words('de', 'Wall P, T').replace(/[.*+?^${}()|[\]\\]/g, '\\$&')));
  const keys = person(page, 'keyboard');
  await keys.type(averageOver, '0,5');
  await page.waitForFunction((n) => [...document.querySelectorAll('#parallel-dom input')]
    .some((e) => e.getAttribute('aria-label') === n && e.value === '0,5'), averageOver, { timeout: 20_000 })
    .catch(() => {});
  check('a typed "0,5" is read as one half and shown "0,5"', await fieldText(me, averageOver) === '0,5',
        await fieldText(me, averageOver));
  // ... and a typed '0.25' too: the read-out of the averaging window says 0,25.
  await keys.type(averageOver, '0.25');
  const over = words('de', 'P, T over');
  const row = me.dom.locator('p', { hasText: new RegExp('^' + over.replace(/[.*+?^${}()|[\]\\]/g, '\\$&') + ' = .*0,25') });
  check('a typed "0.25" is read too: the read-out says 0,25',
        await row.first().waitFor({ state: 'attached', timeout: 20_000 }).then(() => true, () => false),
        await me.dom.locator('p', { hasText: over }).first().textContent().catch(() => 'no row'));

  // 4. Chinese: the font is fetched only now, and its glyphs are drawn (the view's text is
  //    mirrored, the pixels are looked at in the screenshot).
  const fontRequests = [];
  page.on('request', (r) => { if (/fonts\/noto-sans-sc-subset\.[0-9a-f]{8}\.otf$/.test(r.url())) fontRequests.push(r.url()); });
  check('no Chinese font is fetched for Spanish and German', fontRequests.length === 0);
  const fetched = page.waitForResponse((r) => /fonts\/noto-sans-sc-subset\.[0-9a-f]{8}\.otf$/.test(r.url()), { timeout: 30_000 })
    .then((r) => r.ok(), () => false);
  check('View > Language > 中文（简体） switches to Chinese', await chooseLanguage(me, page, 'de', 'zh-CN'), await language(page));
  check('the Chinese font subset is fetched when Chinese is chosen', await fetched, fontRequests.join(', '));
  await me.find('menuitem', '视图').waitFor({ state: 'attached', timeout: 30_000 });
  await page.screenshot({ path: join(outDir, 'i18n', 'chinese-chosen.png') });
  console.log('      screenshot -> build/web-test/i18n/chinese-chosen.png');

  // 5. Remembered: the next visit, with no #lang=, starts in Chinese.
  await page.close();
  ({ page, started, error } = await openApp(url, 'i18n-again'));
  check('the next visit starts', started, error || '');
  check('the choice is remembered for the next visit', await until(page, 'zh-CN'), await language(page));

  // 6. Copy link carries the language, and a link's #lang= beats the remembered choice.
  const again = person(page, 'mouse');
  await again.press('button', words('zh-CN', 'Copy link'));
  await page.waitForFunction(() => location.hash.startsWith('#lang='), null, { timeout: 20_000 }).catch(() => {});
  const hash = await page.evaluate(() => location.hash);
  check('Copy link puts the language in the link (#lang=zh-CN&...)', /^#lang=zh-CN&(z|preset)=/.test(hash), hash.slice(0, 30));
  await page.evaluate(() => localStorage.setItem('swarmlab.language', 'fr'));
  const link = await page.evaluate(() => location.href);
  await page.close();
  ({ page, started, error } = await openApp(link, 'i18n-link'));
  check('the copied link opens in Chinese though French was remembered', started && await until(page, 'zh-CN'),
        error || await language(page));
  await page.close();

  // 7. Windows opened in one language are named in the next (the parallel DOM's regions): a
  //    saved progress that cannot be read opens the Lesson progress window in Spanish, then
  //    View > Language > Deutsch.
  ({ page, started, error } = await openApp(url + '#lang=es', 'i18n-windows', () =>
    localStorage.setItem('swarmlab.progress', '{"version": 1, "welcomed": true, "lessons": {"one-per')));
  if (check('the page opens in Spanish with unreadable progress', started && await until(page, 'es'), error || '')) {
    const regions = () => page.evaluate(() => [...document.querySelectorAll('#parallel-dom .pdom-region')]
      .map((r) => r.getAttribute('aria-label')));
    const windows = ['Lesson progress', 'Controls', 'Plots'];
    await page.waitForFunction((name) => [...document.querySelectorAll('#parallel-dom .pdom-region')]
      .some((r) => r.getAttribute('aria-label') === name), words('es', 'Lesson progress'), { timeout: 30_000 }).catch(() => {});
    const spanish = await regions();
    check('the Lesson progress window opens, named in Spanish', spanish.includes(words('es', 'Lesson progress')), spanish.join(', '));
    const mouse = person(page, 'mouse');
    check('View > Language > Deutsch', await chooseLanguage(mouse, page, 'es', 'de'), await language(page));
    await page.waitForFunction((name) => [...document.querySelectorAll('#parallel-dom .pdom-region')]
      .some((r) => r.getAttribute('aria-label') === name), words('de', 'Lesson progress'), { timeout: 30_000 }).catch(() => {});
    const german = await regions();
    check('every window is named in German now: Lesson progress, Controls, Plots (none left in Spanish)',
          windows.every((w) => german.includes(words('de', w)) && !german.includes(words('es', w))), german.join(', '));
    check('the Lesson progress window\'s close button is named in German',
          await mouse.find('button', words('de', 'Close %s').replace('%s', words('de', 'Lesson progress'))).count() === 1);
    await page.close();
  }
  await closeBrowser();

  // 8. Per language, for a person to look at: a lesson's first step at a laptop size, and the
  //    welcome on a phone (each written to build/web-test/i18n/).
  await launchBrowser({ width: 1366, height: 768 });
  for (const code of LANGUAGES) {
    ({ page, started, error } = await openApp(`${url}#lang=${code}&lesson=${firstLesson.id}`, `i18n-lesson-${code}`));
    if (check(`${code}: a lesson link opens in that language`, started && await until(page, code), error || '')) {
      const title = words(code, firstLesson.title);
      const heading = page.locator('#parallel-dom').getByText(title, { exact: false }).first();
      check(`${code}: the lesson's title is translated ("${title.slice(0, 30)}")`,
            await heading.waitFor({ state: 'attached', timeout: 30_000 }).then(() => true, () => false));
      await page.screenshot({ path: join(outDir, 'i18n', `lesson-${code}-1366x768.png`) });
    }
    await page.close();
  }
  await closeBrowser();
  await launchBrowser({ width: 390, height: 844, hasTouch: true, isMobile: true });
  for (const code of LANGUAGES) {
    // Each a first visit: no progress kept from the language before.
    ({ page, started, error } = await openApp(`${url}?welcome#lang=${code}`, `i18n-welcome-${code}`,
                                              () => localStorage.removeItem('swarmlab.progress')));
    if (check(`${code}: the welcome opens on a phone`, started && await until(page, code), error || '')) {
      const welcome = await page.waitForFunction(() => window.swarmlab.welcomeShown(), null, { timeout: 30_000 })
        .then(() => true, () => false);
      check(`${code}: the welcome shows`, welcome);
      await page.screenshot({ path: join(outDir, 'i18n', `welcome-${code}-390x844.png`) });
    }
    await page.close();
    // The same lesson step on the phone: the view, the transport and the lesson's drawer.
    ({ page, started, error } = await openApp(`${url}#lang=${code}&lesson=${firstLesson.id}`, `i18n-phone-${code}`));
    if (check(`${code}: the lesson opens on a phone`, started && await until(page, code), error || '')) {
      await page.waitForFunction(() => window.swarmlab.state().layout_settled, null, { timeout: 30_000 }).catch(() => {});
      await page.screenshot({ path: join(outDir, 'i18n', `lesson-${code}-390x844.png`) });
    }
    await page.close();
  }
  await closeBrowser();

  // 9. A browser set to a language by its locale, by the table's aliases (web/page_text.js reads
  //    them from page_texts.js): each language whose code is not its alias (Portugal's
  //    Portuguese gets Brazil's) starts in it, and the pseudo-language's page is marked as the
  //    texts' own language for screen readers.
  const byAlias = ROWS.filter((l) => !l.pseudo && l.aliases.length && l.aliases[0] !== l.code.toLowerCase());
  for (const l of byAlias) {
    const locale = `${l.aliases[0]}-PT`;  // any region: only the primary subtag counts
    await launchBrowser({ width: 1280, height: 720, locale });
    ({ page, started, error } = await openApp(url, `i18n-locale-${l.code}`));
    check(`a browser set to ${locale} starts in ${l.code} (its aliases: ${l.aliases.join(', ')})`,
          started && await until(page, l.code), error || await language(page));
    await page.close();
    await closeBrowser();
  }
  await launchBrowser({ width: 1280, height: 720 });
  const pseudo = ROWS.find((r) => r.pseudo).code;
  ({ page, started, error } = await openApp(`${url}#lang=${pseudo}`, 'i18n-pseudo'));
  check(`#lang=${pseudo}: the app speaks it, and the page is marked ${SOURCE}`,
        started && await until(page, pseudo) && await page.evaluate(() => document.documentElement.lang) === SOURCE,
        error || await page.evaluate(() => document.documentElement.lang));
  await page.close();
  await closeBrowser();
  console.log('      screenshots -> build/web-test/i18n/');
  check('no page errors', pageErrors.length === 0, pageErrors.join(' | '));
}

await runSuite('i18n', 240_000, main);
