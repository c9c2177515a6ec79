// The page in a second engine: Debian's Firefox ESR driven by geckodriver through
// selenium-webdriver (WebDriver BiDi for the console). Headless Firefox has no WebGL2 on these
// machines, so scripts/test.sh runs this headed under Xvfb (xvfb-run) with Mesa's software
// renderer. Every scene must draw (pixels differ from the background), with no console error,
// no uncaught exception and no failed request.
// Usage: xvfb-run -a node tests/firefox/smoke.mjs
import { Builder, By, until } from 'selenium-webdriver';
import firefox from 'selenium-webdriver/firefox.js';
import LogInspector from 'selenium-webdriver/bidi/logInspector.js';
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { startServer } from '../../scripts/serve.mjs';
import { decodePng, countDifferent } from '../page/png.mjs';

const { server, url } = await startServer();
// a course page of another site: a sandboxed iframe and a <ruled-view controls> in a 280-px column
const siteDir = mkdtempSync(join(tmpdir(), 'ruledlab-firefox-site-'));
const site = await startServer({ root: siteDir });
const host = (/** @type {string} */ body) =>
  `<!doctype html><html lang="en"><head><meta charset="utf-8"><link rel="icon" href="data:,"><title>course</title><script defer src="${url}dist/ruledlab-embed.js"></script></head><body style="margin: 10px">${body}</body></html>`;
writeFileSync(
  join(siteDir, 'sandbox.html'),
  host(
    `<iframe id="f" sandbox="allow-scripts" src="${url}index.html#embed&amp;controls&amp;paper=fig2" title="ruledlab" width="800" height="520"></iframe>`,
  ),
);
writeFileSync(
  join(siteDir, 'column.html'),
  host('<div style="width: 280px"><ruled-view id="v" paper="fig2" controls height="560"></ruled-view></div>'),
);
const options = new firefox.Options().enableBidi().windowSize({ width: 1100, height: 800 });
options.setBinary(process.env.FIREFOX ?? '/usr/bin/firefox-esr');
options.setPreference('webgl.force-enabled', true);
const service = new firefox.ServiceBuilder(process.env.GECKODRIVER ?? 'geckodriver');
const driver = await new Builder().forBrowser('firefox').setFirefoxOptions(options).setFirefoxService(service).build();

/** @type {string[]} */
const problems = [];
let failed = 0;
try {
  const inspector = await LogInspector(driver);
  await inspector.onConsoleEntry((/** @type {any} */ entry) => {
    if (entry.level === 'error') problems.push(`console error: ${entry.text}`);
  });
  await inspector.onJavascriptException((/** @type {any} */ entry) => problems.push(`exception: ${entry.text}`));

  await driver.get(url);
  await driver.wait(until.elementLocated(By.css('.rl-stage[data-ready="1"]')), 60000);
  const webgl2 = await driver.executeScript('return !!document.createElement("canvas").getContext("webgl2")');
  if (!webgl2) throw new Error('Firefox has no WebGL2 here: run under xvfb-run (headed), not headless');
  const scenes = /** @type {string[]} */ (await driver.executeScript('return window.ruledlab.scenes.map((s) => s.id)'));
  const background = /** @type {number[]} */ (
    await driver.executeScript(
      'const c = getComputedStyle(document.querySelector(".rl-view")).getPropertyValue("--rl-bg") || getComputedStyle(document.body).backgroundColor; return c.match(/\\d+/g).slice(0, 3).map(Number)',
    )
  );
  for (const scene of scenes) {
    const before = problems.length;
    // a fresh load of each scene: from a blank page, not a refresh right after the link's change,
    // which would cancel the CAM module's import that the scene's opening began (Firefox reports
    // the cancelled import as an error of the page it left)
    await driver.get('about:blank');
    await driver.get(`${url}#scene=${scene}`);
    await driver.wait(until.elementLocated(By.css('.rl-stage[data-ready="1"]')), 60000);
    await driver.sleep(300);
    const canvas = await driver.findElement(By.css('.rl-view canvas'));
    const image = decodePng(Buffer.from(await canvas.takeScreenshot(), 'base64'));
    const drawn = countDifferent(image, background, 24) / (image.width * image.height);
    const failedRequests = /** @type {string[]} */ (
      await driver.executeScript(
        "return performance.getEntriesByType('resource').filter((e) => e.responseStatus >= 400).map((e) => e.name)",
      )
    );
    failedRequests.forEach((r) => {
      problems.push(`failed request: ${r}`);
    });
    const ok = drawn > 0.005 && problems.length === before;
    if (!ok) failed++;
    console.log(
      `${ok ? 'ok' : 'not ok'} - Firefox: ${scene} draws (${(100 * drawn).toFixed(1)} % of the view)${problems
        .slice(before)
        .map((p) => `\n  ${p}`)
        .join('')}`,
    );
  }
  // a drag of a ruling's endpoint (the pointer, as WebDriver moves it): exactly that handle moves,
  // the edit lands in the link, and undo brings the built-in input back
  {
    const before = problems.length;
    await driver.get(`${url}#scene=striction&n=10`);
    await driver.navigate().refresh();
    await driver.wait(until.elementLocated(By.css('.rl-stage[data-ready="1"]')), 60000);
    await driver.sleep(300);
    const canvas = await driver.findElement(By.css('.rl-view canvas'));
    // a handle well inside the view, far from the others (CSS px from the canvas's centre)
    const pick = /** @type {{k: number, dx: number, dy: number, points: number[]}} */ (
      await driver.executeScript(`const s = window.ruledlab.stage, c = s.viewer.canvas, w = c.clientWidth, h = c.clientHeight;
        const m = s.viewer.camera.viewProj(w / h);
        const at = s.editor.handles().map((g) => { const [x, y, z] = g.world, q = m[3] * x + m[7] * y + m[11] * z + m[15];
          return { x: ((m[0] * x + m[4] * y + m[8] * z + m[12]) / q + 1) / 2 * w, y: (1 - (m[1] * x + m[5] * y + m[9] * z + m[13]) / q) / 2 * h }; });
        const free = at.map((p, k) => ({ ...p, k })).filter((p) => p.x > 60 && p.x < w - 60 && p.y > 90 && p.y < h - 90 && at.every((o, j) => j === p.k || Math.hypot(o.x - p.x, o.y - p.y) > 24));
        const p = free.sort((a, b) => Math.hypot(a.x - w / 2, a.y - h / 2) - Math.hypot(b.x - w / 2, b.y - h / 2))[0];
        if (!p) return { k: -1, dx: 0, dy: 0, points: [], at: at.map((q) => [Math.round(q.x), Math.round(q.y)]), w, h };
        return { k: p.k, dx: Math.round(p.x - w / 2), dy: Math.round(p.y - h / 2), points: Array.from(s.currentInput().rulings) };`)
    );
    if (pick.k < 0) throw new Error(`no handle stands free in Firefox's view: ${JSON.stringify(pick)}`);
    await driver
      .actions()
      .move({ origin: canvas, x: pick.dx, y: pick.dy })
      .press()
      .move({ origin: canvas, x: pick.dx + 20, y: pick.dy - 15, duration: 150 })
      .move({ origin: canvas, x: pick.dx + 40, y: pick.dy - 30, duration: 150 })
      .release()
      .perform();
    await driver.sleep(300);
    const after = /** @type {{points: number[], link: boolean}} */ (
      await driver.executeScript(
        'return { points: Array.from(window.ruledlab.stage.currentInput().rulings), link: /[#&]input=rulings\\./.test(location.hash) }',
      )
    );
    const moved = [];
    for (let i = 0; 3 * i < pick.points.length; i++)
      if ([0, 1, 2].some((c) => pick.points[3 * i + c] !== after.points[3 * i + c])) moved.push(i);
    await driver.executeScript('window.ruledlab.stage.editor.undo()');
    const undone = /** @type {boolean} */ (await driver.executeScript('return window.ruledlab.stage.input === null'));
    const ok = moved.length === 1 && moved[0] === pick.k && after.link && undone && problems.length === before;
    if (!ok) failed++;
    console.log(
      `${ok ? 'ok' : 'not ok'} - Firefox: a drag moves exactly the handle taken (${moved.join(', ')} for ${pick.k}), the edit is in the link (${after.link}), undo restores (${undone})${problems
        .slice(before)
        .map((p) => `\n  ${p}`)
        .join('')}`,
    );
  }
  // the sandboxed iframe (an opaque origin: no storage, no history) draws with its controls
  {
    const before = problems.length;
    await driver.get(`${site.url}sandbox.html`);
    await driver.switchTo().frame(await driver.findElement(By.id('f')));
    await driver.wait(until.elementLocated(By.css('.rl-stage[data-ready="1"]')), 60000);
    await driver.sleep(300);
    const controls = (await driver.findElements(By.css('.rl-controls [name]'))).length;
    const image = decodePng(
      Buffer.from(await (await driver.findElement(By.css('.rl-view canvas'))).takeScreenshot(), 'base64'),
    );
    await driver.switchTo().defaultContent();
    const drawn = countDifferent(image, background, 24) / (image.width * image.height);
    const ok = drawn > 0.005 && controls >= 5 && problems.length === before;
    if (!ok) failed++;
    console.log(
      `${ok ? 'ok' : 'not ok'} - Firefox: a sandboxed iframe (allow-scripts) draws (${(100 * drawn).toFixed(1)} %) with ${controls} controls${problems
        .slice(before)
        .map((p) => `\n  ${p}`)
        .join('')}`,
    );
  }
  // <ruled-view controls> in a 280-px column: the panel scrolls inside the element's box under the view
  {
    const before = problems.length;
    await driver.get(`${site.url}column.html`);
    await driver.wait(
      async () => (await driver.executeScript('return document.getElementById("v")?.dataset.ready')) === '1',
      60000,
    );
    const view = await driver.findElement(By.id('v'));
    const geometry = () =>
      /** @type {Promise<{element: DOMRect, view: DOMRect, panel: DOMRect, scrolled: number, last: DOMRect}>} */ (
        driver.executeScript(`const v = document.getElementById('v'), r = v.shadowRoot, c = [...r.querySelectorAll('.rl-controls [name]')];
          return { element: v.getBoundingClientRect().toJSON(), view: r.querySelector('.rl-view').getBoundingClientRect().toJSON(), panel: r.querySelector('.rl-panel').getBoundingClientRect().toJSON(), scrolled: r.querySelector('.rl-panel').scrollTop, last: c[c.length - 1].getBoundingClientRect().toJSON() };`)
      );
    const g0 = await geometry();
    // the wheel over the panel, a notch at a time, until its last control is in sight inside the box
    const panel = await driver.executeScript(
      'return document.getElementById("v").shadowRoot.querySelector(".rl-panel")',
    );
    let g1 = g0;
    let inside = false;
    for (let k = 0; k < 40 && !inside; k++) {
      await driver
        .actions()
        .scroll(0, 0, 0, 80, /** @type {any} */ (panel))
        .perform();
      await driver.sleep(60);
      g1 = await geometry();
      inside = g1.last.bottom <= Math.min(g1.element.bottom, g1.panel.bottom) + 1 && g1.last.top >= g1.panel.top - 1;
    }
    const share = g0.view.height / g0.element.height;
    const image = decodePng(Buffer.from(await view.takeScreenshot(), 'base64'));
    const drawn = countDifferent(image, background, 24) / (image.width * image.height);
    const ok = g1.scrolled > 0 && inside && share >= 0.55 && drawn > 0.005 && problems.length === before;
    if (!ok) failed++;
    console.log(
      `${ok ? 'ok' : 'not ok'} - Firefox: <ruled-view controls> in a 280-px column: the view keeps ${(100 * share).toFixed(0)} %, the panel scrolls by the wheel to its last control inside the box (${inside})${problems
        .slice(before)
        .map((p) => `\n  ${p}`)
        .join('')}`,
    );
  }
} finally {
  await driver.quit();
  server.close();
  site.server.close();
}
if (failed || problems.length) {
  console.error(`Firefox smoke test: ${failed} scene(s) failed; ${problems.length} problem(s)`);
  process.exit(1);
}
console.log(
  'Firefox smoke test: every scene draws, a drag edits the geometry, a sandboxed iframe and a 280-px column draw too; no console error, no failed request',
);
