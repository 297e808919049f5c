// The classroom in the browser: keyboard-only operation (ImGui's keyboard navigation, no
// mouse), the screen reader's live region and the page title following the state, the light
// theme and presentation mode through swarmlab.set() (a screenshot at 1280x720), and sound on
// and off. Run through tests/web/run.sh; the last line is "N passed, M failed".
import * as harness from './harness.mjs';

const { check, openApp, launchBrowser, runSuite, screenshot, clockStands, pageErrors, consoleErrors,
        DEFAULT_PRESET } = harness;

async function main(url) {
  const context = await launchBrowser({ width: 1280, height: 720 });
  const blank = context.pages()[0];
  const { page, started, error } = await openApp(url, 'access');
  if (blank) await blank.close();
  if (!check('the app starts', started, error || '')) return;

  const api = (expr, arg) => page.evaluate(expr, arg);
  const appState = () => api(() => window.swarmlab.state());
  const spoken = () => api(() => document.getElementById('announcer').textContent);
  // Waits until fn(state(), arg) holds in the page (what an action should change), or 15 s pass;
  // returns whether it held. fn runs in the page: what it needs from here comes in arg. (A
  // function made here: the page's CSP refuses the eval a predicate given as text needs.)
  const until = (fn, arg = null) => page.waitForFunction(new Function('arg', `return (${fn})(window.swarmlab.state(), arg);`), arg,
                                                         { timeout: 15_000 }).then(() => true, () => false);
  const untilPage = (fn, arg = null) => page.waitForFunction(fn, arg, { timeout: 15_000 }).then(() => true, () => false);
  // A key or chord as a person presses it (the app takes a press between two frames as one),
  // then a wait for what it should change: the next key comes only after the app has seen it.
  const press = async (chord, effect = null, arg = null) => {
    await page.keyboard.press(chord);
    return effect ? until(effect, arg) : true;
  };
  // F6 moves the keyboard to the next region as in desktop apps (Shift+F6 back); pressed until
  // `wanted` has the keyboard focus, at most once round all regions. Returns where it went.
  const focusRegion = async (wanted, chord = 'F6') => {
    const visited = [];
    for (let k = 0; k < 10; ++k) {
      await press(chord, (s, before) => s.keyboard_focus !== before, (await appState()).keyboard_focus);
      const focus = (await appState()).keyboard_focus;
      visited.push(focus);
      if (wanted.includes(focus)) break;
    }
    return visited;
  };

  // 1. What the page says at the start: the live region and the title.
  const region = await api(() => {
    const r = document.getElementById('announcer');
    return r && { role: r.getAttribute('role'), live: r.getAttribute('aria-live'), width: r.getBoundingClientRect().width };
  });
  check('an off-screen live region: role="status" aria-live="polite"',
        region && region.role === 'status' && region.live === 'polite' && region.width <= 1, JSON.stringify(region));
  check('the live region names the preset and says it plays',
        (await spoken()).startsWith(`${DEFAULT_PRESET}. Playing, t = `), await spoken());
  const title = await page.title();
  check('the page title says what runs', title === `Swarm Lab \u2014 ${DEFAULT_PRESET}, playing`, title);

  // 2. Keyboard only: the page has focus (as after a Tab into it) but no mouse event reaches
  // the app. F6 walks the regions in reading order; in the transport bar the first control is
  // Play/Pause, and Space presses it.
  await page.focus('#canvas');
  // The wide layout's regions in reading order (null: the 3D view), round and round.
  const order = ['menu', 'Controls', 'Transport', null, 'Read-outs', 'Timeline', 'Plots'];
  const walk = await focusRegion(['Transport']);
  const start = order.indexOf(walk[0]);
  check('F6 walks the regions in reading order to the transport bar',
        start >= 0 && walk.at(-1) === 'Transport' && walk.every((r, i) => r === order[(start + i) % order.length]),
        `keyboard focus: ${walk.map(String).join(' > ')}`);
  const inView = await focusRegion([null]);
  check('F6 from the transport bar goes to the 3D view (no panel has the keys)',
        inView.length === 1 && inView[0] === null, `keyboard focus: ${inView.map(String).join(' > ')}`);
  const back = await focusRegion(['Transport'], 'Shift+F6');
  check('Shift+F6 goes back to the transport bar', back.join(' > ') === 'Transport', `keyboard focus: ${back.map(String).join(' > ')}`);
  const ctrlF6 = await focusRegion([null], 'Control+F6');
  check('Ctrl+F6 moves on as F6 does', ctrlF6.length === 1 && ctrlF6[0] === null, `keyboard focus: ${ctrlF6.map(String).join(' > ')}`);
  await focusRegion(['Transport'], 'Shift+F6');
  // Ctrl+Tab is the browser's (its tabs): the app's keyboard focus stays where it is, so the F6
  // after it goes on from the transport bar to the 3D view.
  await press('Control+Tab');
  const afterCtrlTab = await focusRegion([null]);
  check('Ctrl+Tab does not move the app\'s keyboard focus', afterCtrlTab.map(String).join(' > ') === 'null',
        `Ctrl+Tab, then F6: ${afterCtrlTab.map(String).join(' > ')}`);
  await focusRegion(['Transport'], 'Shift+F6');
  const item = (await appState()).keyboard_item;
  await press('Space', (st) => st.playing === false);
  // Once: a second toggle (the shortcut as well as the button) would have it play again.
  const stands = await clockStands(page);
  let s = await appState();
  check('Space on the focused Pause button pauses (once: the Space shortcut stands aside)', s.playing === false && stands.ok,
        `on "${item}": playing ${s.playing}, ${stands.detail}`);
  await untilPage(() => /Paused, t = /.test(document.getElementById('announcer').textContent));
  check('the live region says paused', /Paused, t = /.test(await spoken()), await spoken());
  await untilPage(() => document.title.endsWith(', paused'));
  check('the title says paused', (await page.title()).endsWith(', paused'), await page.title());
  await press('Space', (st) => st.playing === true);
  s = await appState();
  check('Space again plays', s.playing === true, `playing ${s.playing}`);

  // A preset change through the menu bar: F6 to it, Space opens Scenario (the keyboard on its
  // first entry), Down moves in its list, Space opens the preset focused.
  const shipped = await api(() => window.swarmlab.shipped());
  const before = (await appState()).name;
  const menuFocus = (await focusRegion(['menu'])).pop();
  const menuTitle = (await appState()).keyboard_item;
  await press('Space', (st, t) => st.windows.some((w) => /^##Menu/.test(w.name)) && st.keyboard_item && st.keyboard_item !== t, menuTitle);
  const entry = (await appState()).keyboard_item;
  await press('ArrowDown', (st, e) => st.keyboard_item && st.keyboard_item !== e, entry);
  const next = (await appState()).keyboard_item;
  await press('Space', (st, b) => st.name !== b, before);
  s = await appState();
  check('F6 to the menu bar, Space, Down, Space opens another shipped preset',
        s.name !== before && shipped.some((p) => p.name === s.name) && s.name === next,
        `focus: ${menuFocus} "${menuTitle}", then "${entry}", "${next}"; "${before}" -> "${s.name}"`);
  await untilPage((name) => document.getElementById('announcer').textContent.includes(name), s.name);
  check('the live region says the new preset\'s name', (await spoken()).includes(s.name), await spoken());
  await untilPage((name) => document.title.includes(name), s.name);
  check('the title follows the preset', (await page.title()).includes(s.name), await page.title());

  // 3. The light theme and presentation mode through swarmlab.set(): the pixels change (on
  // the app's next frame: the screenshot is taken again until they have).
  const bright = (img) => parseInt(img.topColor.slice(1), 16) >= 0xddd;
  const dark = await screenshot(page, 'access-dark-1280x720.png', {});
  await api(() => window.swarmlab.set({ theme: 'light' }));
  const light = await screenshot(page, 'access-light-1280x720.png', {}, bright);
  check('set({theme: "light"}) turns the page light', !bright(dark) && bright(light) && (await appState()).theme === 'light',
        `most common colour ${dark.topColor} -> ${light.topColor}`);
  await api(() => window.swarmlab.set({ presentation: true, theme: 'dark' }));  // table order: presentation wins
  s = await appState();
  const shown = await screenshot(page, 'access-presentation-1280x720.png', {}, bright);
  check('set({presentation: true}): light theme, a light screen', s.presentation === true && s.theme === 'light' && bright(shown),
        `theme ${s.theme}, most common colour ${shown.topColor} ${(100 * shown.topShare).toFixed(0)}%`);
  await api(() => window.swarmlab.set({ presentation: false }));
  s = await appState();
  check('set({presentation: false}) gives the dark theme back', s.presentation === false && s.theme === 'dark', `theme ${s.theme}`);

  // set() refuses what it does not know, names it, and changes nothing.
  const refusals = await api(() => [{ colour: 'red' }, { theme: 'blue' }, { sound: 'yes', theme: 'light' }, 7].map((v) => {
    try { window.swarmlab.set(v); return 'accepted'; } catch (e) { return e.message; }
  }));
  check('set() with an unknown key throws naming it', /unknown key "colour"/.test(refusals[0]), refusals[0]);
  check('set() with a bad theme throws naming the key and the rule', /theme: must be "dark" or "light"/.test(refusals[1]), refusals[1]);
  check('a refused set() changes nothing', /sound: must be true or false/.test(refusals[2]) && (await appState()).theme === 'dark', refusals[2]);
  check('set() of a non-object throws', /expects an object/.test(refusals[3]), refusals[3]);

  // 4. Sound: off until turned on; on after a gesture makes a running AudioContext; off again.
  check('sound is off at the start', (await appState()).sound === false);
  await page.mouse.click(640, 600);  // a gesture, as the user's click on the toggle would be
  const audioState = () => api(() => ({ sound: window.swarmlab.state().sound, context: Module.swarmlabAudio ? Module.swarmlabAudio.state : null }));
  await api(() => window.swarmlab.set({ sound: true }));
  await untilPage(() => Module.swarmlabAudio && Module.swarmlabAudio.state === 'running');
  let audio = await audioState();
  check('set({sound: true}) after a gesture: sound on, the AudioContext runs', audio.sound === true && audio.context === 'running',
        JSON.stringify(audio));
  await api(() => window.swarmlab.set({ sound: false }));
  await untilPage(() => Module.swarmlabAudio && Module.swarmlabAudio.state !== 'running');
  audio = await audioState();
  check('set({sound: false}): sound off, the AudioContext suspended', audio.sound === false && audio.context !== 'running',
        JSON.stringify(audio));

  // 5. Fullscreen from the key: this Chromium grants it after a key press (a browser that
  // refuses has the app say so in the scenario panel); never an error.
  await page.keyboard.press('F11');
  await until((st) => st.fullscreen === true);
  s = await appState();
  const inPage = await api(() => document.fullscreenElement !== null);
  check('F11 asks for fullscreen: granted, and state().fullscreen says so', s.fullscreen === true && inPage,
        `state().fullscreen ${s.fullscreen}, document.fullscreenElement ${inPage ? 'set' : 'null'}`);

  check('no page errors', pageErrors.length === 0, pageErrors.join(' | '));
  check('no console errors', consoleErrors.length === 0, consoleErrors.join(' | '));
}

runSuite('access_e2e', 140_000, main);
