import * as h from './harness.mjs';
await h.runSuite('cost', 120000, async (url) => {
  await h.launchBrowser({ width: 1366, height: 768 });
  const { page } = await h.openApp(url, 'cost');
  await page.waitForSelector('#parallel-dom button');
  const r = await page.evaluate(() => {
    const n = 200;
    let t0 = performance.now(), bytes = 0, items = 0;
    for (let i = 0; i < n; ++i) { const s = Module.ccall('swarmlab_dom_items', 'string', [], []); bytes = s.length; items = JSON.parse(s).items.length; }
    const perCall = (performance.now() - t0) / n;
    return { perCall, bytes, items, elements: document.querySelectorAll('#parallel-dom .pdom-item').length };
  });
  const f0 = await page.evaluate(() => [window.swarmlab.frames(), performance.now()]);
  await page.waitForTimeout(3000);
  const f1 = await page.evaluate(() => [window.swarmlab.frames(), performance.now()]);
  const frameMs = (f1[1] - f0[1]) / (f1[0] - f0[0]);
  h.check('cost', true, JSON.stringify({ ...r, frameMs }));
});
