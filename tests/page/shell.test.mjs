// The first paint, as a reader on a phone or a desktop meets it, in the production page
// (`npm start`, dist/web/) and the one-file build: the page's shell is in the HTML, so the linked
// scene's heading (in the link's language) is painted before any module has run, and the
// scripts take that heading over where it is — nothing painted moves (no layout shift at all,
// as the browser's Layout Instability API counts it) from the first byte to the finished view.
// On a phone the header is one row, the name and a Menu button that opens the scene, figure,
// exercise and language pickers and Share over the figure, which follows right under it.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { startServer, SITE } from '../../scripts/serve.mjs';
import { launch, watch, ready } from './browser.mjs';

const PHONE = { viewport: { width: 412, height: 823 }, isMobile: true, hasTouch: true };
/** @type {import('node:http').Server} */
let server;
/** @type {import('node:http').Server} */
let dev;
let url = '';
let devUrl = '';
/** @type {Record<string, import('playwright-core').BrowserContext>} */
const browsers = {};
before(async () => {
  ({ server, url } = await startServer({ root: SITE }));
  ({ server: dev, url: devUrl } = await startServer());
  [browsers.phone, browsers.desktop] = await Promise.all([
    launch(PHONE),
    launch({ viewport: { width: 1350, height: 940 } }),
  ]);
});
after(async () => {
  await Promise.all(Object.values(browsers).map((b) => b.close()));
  server?.close();
  dev?.close();
});

/**
 * Opens `path` with the page's module held back until `release()`: what is on screen then is what
 * the HTML alone paints. Every layout shift from the first byte on is recorded, and the heading
 * painted first is marked, to be found again once the scripts have run.
 * @param {import('playwright-core').BrowserContext} browser @param {string} path
 */
async function held(browser, path) {
  const page = await browser.newPage();
  const problems = watch(page);
  /** @type {() => void} */
  let release = () => {};
  const gate = new Promise((r) => {
    release = () => r(undefined);
  });
  // the production page's entry
  await page.route(/assets\/main-[\w]+\.js$/, async (route) => {
    await gate;
    await route.continue();
  });
  await page.addInitScript(() => {
    const seen = /** @type {any} */ (window);
    seen.shifts = [];
    new PerformanceObserver((list) => {
      for (const e of /** @type {any[]} */ (list.getEntries()))
        seen.shifts.push({ value: e.value, sources: e.sources.map((s) => s.node?.nodeName) });
    }).observe({ type: 'layout-shift', buffered: true });
    document.addEventListener('readystatechange', () => {
      const heading = document.querySelector('.rl-panel > h2');
      if (heading && document.readyState === 'interactive') /** @type {any} */ (heading).paintedFirst = true;
    });
  });
  await page.goto(url + path, { waitUntil: 'commit' });
  return { page, problems, release };
}

/** What the shell shows: the heading, the language, the phone's arrangement, the header's rows. */
const shown = (/** @type {import('playwright-core').Page} */ page) =>
  page.evaluate(() => {
    const header = /** @type {HTMLElement} */ (document.querySelector('header.page-header')).getBoundingClientRect();
    const view = /** @type {HTMLElement} */ (document.querySelector('.rl-view')).getBoundingClientRect();
    return {
      heading: /** @type {HTMLElement} */ (document.querySelector('.rl-panel > h2')).textContent,
      lang: document.documentElement.lang,
      narrow: /** @type {HTMLElement} */ (document.querySelector('.rl-stage')).classList.contains('rl-narrow'),
      header: header.height,
      viewTop: view.top - header.bottom,
      started: document.documentElement.hasAttribute('data-started'),
    };
  });

for (const [name, path, heading, lang] of [
  ['striction', '#scene=striction', /^Striction polygon/, 'en'],
  ['congruence, by its figure of the paper', '#paper=fig13', /^Line congruences/, 'en'],
  ['focal, in German', '#scene=focal&lang=de', /^Brennflächen/, 'de'],
]) {
  test(`the production page's first paint shows the heading of ${name} before any module ran; nothing moves until the view is done (phone and desktop)`, async () => {
    for (const [device, browser] of Object.entries(browsers)) {
      const { page, problems, release } = await held(browser, path);
      await page.locator('.rl-panel > h2').waitFor();
      await page.waitForTimeout(300);
      const first = await shown(page);
      assert.match(first.heading ?? '', heading, device);
      assert.equal(first.lang, lang, device);
      assert.equal(first.started, false, `${device}: the page's module ran before this look`);
      assert.equal(first.narrow, device === 'phone', device);
      release();
      await ready(page, 60000);
      await page.waitForTimeout(500);
      const done = await page.evaluate(() => ({
        shifts: /** @type {any} */ (window).shifts,
        same: /** @type {any} */ (document.querySelector('.rl-panel > h2')).paintedFirst === true,
      }));
      assert.deepEqual(done.shifts, [], `${device} ${name}: layout shifts`);
      assert.ok(done.same, `${device}: the scripts replaced the heading painted first`);
      assert.deepEqual(problems, []);
      await page.close();
    }
  });
}

test('the one-file build paints the linked heading with its first bytes, and nothing moves (phone)', async () => {
  const page = await browsers.phone.newPage();
  const problems = watch(page);
  await page.addInitScript(() => {
    const seen = /** @type {any} */ (window);
    seen.shifts = [];
    new PerformanceObserver((list) => {
      for (const e of /** @type {any[]} */ (list.getEntries())) seen.shifts.push(e.value);
    }).observe({ type: 'layout-shift', buffered: true });
  });
  await page.goto(`${url}dist/ruledlab.html#scene=congruence&lang=de`);
  await ready(page, 60000);
  await page.waitForTimeout(500);
  assert.match(/** @type {string} */ (await page.locator('.rl-panel > h2').textContent()), /^Geradenkongruenzen/);
  assert.deepEqual(await page.evaluate(() => /** @type {any} */ (window).shifts), []);
  assert.deepEqual(problems, []);
  await page.close();
});

for (const [which, base] of [
  ['production page', () => url],
  ['unbundled page', () => devUrl],
]) {
  test(`a phone (${which}): the header is one row, the figure right under it; Menu opens the pickers and Share, and closes`, async () => {
    const page = await browsers.phone.newPage();
    const problems = watch(page);
    await page.goto(`${base()}#scene=striction`);
    await ready(page, 60000);
    const look = await shown(page);
    assert.ok(look.header <= 60, `the header is ${look.header} px high`);
    assert.ok(Math.abs(look.viewTop) <= 1, `the figure starts ${look.viewTop} px below the header`);
    for (const id of ['scene', 'paper', 'task', 'lang', 'share'])
      assert.equal(await page.locator(`#${id}`).isVisible(), false, `#${id} shown before the menu opened`);
    const menu = page.locator('#menu');
    const box = /** @type {{width: number, height: number}} */ (await menu.boundingBox());
    assert.ok(box.width >= 44 && box.height >= 44, `the Menu button is ${box.width} × ${box.height}`);
    await menu.tap();
    assert.equal(await menu.getAttribute('aria-expanded'), 'true');
    for (const id of ['scene', 'paper', 'task', 'lang', 'share']) {
      const control = page.locator(`#${id}`);
      assert.ok(await control.isVisible(), `#${id} is not in the open menu`);
      const b = /** @type {{x: number, width: number, height: number}} */ (await control.boundingBox());
      assert.ok(b.x >= 0 && b.x + b.width <= 412 && b.height >= 44, `#${id}: ${JSON.stringify(b)}`);
    }
    // each menu under its label, as wide as the open menu (a long scene title is not cut at half)
    const widths = await page.evaluate(() => {
      const menu = /** @type {HTMLElement} */ (document.getElementById('page-menu'));
      const style = getComputedStyle(menu);
      const inner = menu.clientWidth - Number.parseFloat(style.paddingLeft) - Number.parseFloat(style.paddingRight);
      return ['scene', 'paper', 'task', 'lang'].map((id) => {
        const select = /** @type {HTMLElement} */ (document.getElementById(id));
        const label = /** @type {HTMLElement} */ (select.closest('label')?.querySelector('span'));
        const below = select.getBoundingClientRect().top >= label.getBoundingClientRect().bottom - 1;
        return { id, width: Math.round(select.getBoundingClientRect().width - inner), below };
      });
    });
    assert.deepEqual(
      widths,
      ['scene', 'paper', 'task', 'lang'].map((id) => ({ id, width: 0, below: true })),
    );
    // Escape closes it, and the keyboard is back on the button
    await page.keyboard.press('Escape');
    assert.equal(await page.locator('#scene').isVisible(), false);
    assert.equal(await page.evaluate(() => document.activeElement?.id), 'menu');
    // a choice in it is made, and it closes
    await menu.tap();
    await page.locator('#scene').selectOption('curves');
    await page.locator('.rl-stage[data-scene="curves"][data-ready="1"]').waitFor({ timeout: 60000 });
    assert.equal(await page.locator('#scene').isVisible(), false, 'the menu stayed open');
    assert.equal(await menu.getAttribute('aria-expanded'), 'false');
    // Tab past its last entry closes it (the view it covers takes the keyboard)
    await menu.tap();
    await page.locator('#share').focus();
    await page.keyboard.press('Tab');
    assert.equal(await page.locator('#scene').isVisible(), false, 'the menu stayed open after Tab left it');
    assert.equal(await menu.getAttribute('aria-expanded'), 'false');
    // Share, from the menu
    await menu.tap();
    await page.locator('#share').tap();
    await page.locator('#share-dialog[open]').waitFor();
    assert.deepEqual(problems, []);
    await page.close();
  });
}
