// A person at the app: finds what to press by its role and name in the parallel DOM
// (web/README.md, "Parallel DOM") and presses it with real input: a finger (CDP touch events),
// a mouse, or the keyboard alone (Tab to it, then Enter). Never window.swarmlab.* to act; it
// may read state. Every wait is on a condition, never on a frame count or a sleep.

/** The person's ways: 'touch', 'mouse' or 'keyboard'. */
export function person(page, way) {
  const dom = page.locator('#parallel-dom');
  let cdp = null;
  const touchSession = async () => (cdp ||= await page.context().newCDPSession(page));

  async function touch(type, points) {
    const session = await touchSession();
    await session.send('Input.dispatchTouchEvent', {
      type, touchPoints: points.map(([x, y]) => ({ x, y, radiusX: 4, radiusY: 4, force: 1, id: 0 })),
    });
  }
  async function tapAt(x, y) {
    await touch('touchStart', [[x, y]]);
    await touch('touchEnd', []);
  }
  // A finger's drag from (x, y) by dy, in steps, as a hand moves.
  async function swipe(x, y, dy) {
    await touch('touchStart', [[x, y]]);
    const steps = 8;
    for (let i = 1; i <= steps; ++i) await touch('touchMove', [[x, y + (dy * i) / steps]]);
    await touch('touchEnd', []);
  }

  /** The element of the item `name` with `role` (exact name, or a RegExp). */
  function find(role, name) {
    return dom.getByRole(role, { name, exact: typeof name === 'string' }).first();
  }

  const box = (el) => el.evaluate((e) => {
    const r = e.getBoundingClientRect();
    return { x: r.x, y: r.y, width: r.width, height: r.height, clipped: e.dataset.clipped === 'true' };
  });
  const regionBox = (el) => el.evaluate((e) => {
    // The window it is in: the union of its region's visible items.
    const items = [...e.closest('.pdom-region').querySelectorAll('.pdom-item')].filter((c) => c.dataset.clipped !== 'true');
    const rects = items.map((c) => c.getBoundingClientRect());
    return { top: Math.min(...rects.map((r) => r.top)), bottom: Math.max(...rects.map((r) => r.bottom)),
             left: Math.min(...rects.map((r) => r.left)), right: Math.max(...rects.map((r) => r.right)) };
  });

  /** Brings the item into sight as the person would: a finger or the wheel scrolls its panel. */
  async function reveal(el) {
    for (let tries = 0; tries < 20; ++tries) {
      const b = await box(el);
      if (!b.clipped) return b;
      const r = await regionBox(el);
      const x = (r.left + r.right) / 2;
      const down = b.y > r.bottom;  // below what shows: move the content up
      const span = Math.max(40, Math.min(r.bottom - r.top - 20, 240));
      if (way === 'touch') await swipe(x, down ? r.bottom - 10 : r.top + 10, down ? -span : span);
      else { await page.mouse.move(x, (r.top + r.bottom) / 2); await page.mouse.wheel(0, down ? span : -span); }
      // A swipe that did not scroll (on a starved machine its first move can come late enough
      // to count as a finger held still) is swiped again, as a person would.
      await page.waitForFunction(([e, y]) => e.dataset.clipped !== 'true' || e.getBoundingClientRect().y !== y,
                                 [await el.elementHandle(), b.y], { timeout: 10_000 }).catch(() => {});
    }
    throw new Error('could not scroll to ' + (await el.evaluate((e) => e.textContent || e.getAttribute('aria-label'))));
  }

  /** The item's box once it has held still between two frames of the app's loop, or while the
   *  loop sleeps (nothing changes until an input), as Playwright waits before a click: a panel
   *  scrolls new feedback into view on the frame after it appears, moving the buttons below. */
  async function still(el) {
    const handle = await el.elementHandle();
    const held = await page.waitForFunction((e) => {
      const r = e.getBoundingClientRect();
      const clipped = e.dataset.clipped === 'true';
      const place = [r.x, r.y, r.width, r.height, clipped].join();
      const frame = window.swarmlab.frames();
      const last = e.stillSeen;
      if (!last || last.place !== place) e.stillSeen = { place, frame };
      const isStill = last && last.place === place && (frame > last.frame || window.swarmlab.sleeping());
      return isStill && { x: r.x, y: r.y, width: r.width, height: r.height, clipped };
    }, handle, { timeout: 20_000 });
    return held.jsonValue();
  }

  /** Held still in sight, scrolled there first if it is not (it may move out of sight while
   *  settling). */
  async function inSightAndStill(el) {
    for (let tries = 0; tries < 5; ++tries) {
      const b = await still(el);
      if (!b.clipped) return b;
      await reveal(el);
    }
    throw new Error('the item would not stay in sight');
  }

  /** Tab (or Shift+Tab) until the element has the focus, as a keyboard user walks: counts the
   *  focusable elements between the focus and the target, presses Tab up to that many times,
   *  looks again. */
  async function tabTo(el) {
    let presses = 0;
    for (let looks = 0; looks < 80; ++looks) {
      // The locator finds the element anew at each look (an item scrolled out of its panel
      // and back is a new element).
      const steps = await el.evaluate((e) => {
        const all = [...document.querySelectorAll('#parallel-dom button, #parallel-dom input')];
        const to = all.indexOf(e), from = all.indexOf(document.activeElement);
        if (to < 0) return null;
        // From outside the mirrored items: Tab enters at the first, Shift+Tab at the last.
        if (from < 0) return to < all.length / 2 ? 1 : -1;
        // The shorter way: past the last item Tab comes round to the first.
        const ahead = to - from, n = all.length;
        return ahead > n / 2 ? ahead - n : ahead < -n / 2 ? ahead + n : ahead;
      });
      if (steps === 0) return presses;
      if (steps === null) throw new Error('the element is not among the focusable items');
      // In batches, looking again between them: the list changes as panels scroll to the
      // focus (a list scrolled out of its panel leaves the page until it is back in view).
      const key = steps > 0 ? 'Tab' : 'Shift+Tab';
      const batch = Math.min(Math.abs(steps), 12);
      for (let i = 0; i < batch; ++i) await page.keyboard.press(key);
      presses += batch;
    }
    throw new Error('Tab never reached the element');
  }

  /** Presses the item: a tap, a click, or Tab to it and Enter. */
  async function press(role, name) {
    const el = find(role, name);
    await el.waitFor({ state: 'attached' });
    if (way === 'keyboard') {
      await tabTo(el);
      await page.keyboard.press('Enter');
      return;
    }
    const b = await inSightAndStill(el);
    const x = b.x + b.width / 2, y = b.y + b.height / 2;
    if (way === 'touch') await tapAt(x, y);
    else await page.mouse.click(x, y);
  }

  /** Types text into the field named `name` and presses Enter (a phone's "done"). */
  async function type(name, text, role = 'textbox') {
    const el = find(role, name);
    await el.waitFor({ state: 'attached' });
    if (way === 'keyboard') await tabTo(el);
    else if (way === 'touch') {
      const b = await inSightAndStill(el);
      await tapAt(b.x + b.width / 2, b.y + b.height / 2);
    } else throw new Error('person.type: a mouse user types with the keyboard (use keyboard)');
    // The field's <input> has the focus now (for a finger: once the app opened the field).
    await page.waitForFunction((e) => document.activeElement === e, await el.elementHandle(), { timeout: 10_000 });
    await page.keyboard.press('Control+A');
    await page.keyboard.type(String(text));
    await page.keyboard.press('Enter');
  }

  return { way, dom, find, press, type, tapAt, swipe, reveal, tabTo };
}
