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

// The first figure is readied off the page's tasks (viewer.js's prepareFirst): drawn into the
// framebuffer while the GPU's work is waited for between tasks, so that the frame showing it
// only resolves the target onto the canvas — and shows what a frame drawn anew shows.
test('the first frame of a view resolves the figure drawn before it, and shows what a new frame draws', async () => {
  const page = await browsers.desktop.newPage();
  const problems = watch(page);
  await page.goto(`${url}#scene=striction`);
  await ready(page, 60000);
  const seen = await page.evaluate(async () => {
    const { stage } = /** @type {any} */ (window).ruledlab;
    const Viewer = stage.viewer.constructor;
    const canvas = document.createElement('canvas');
    canvas.style.cssText = 'position: fixed; left: 0; top: 0; width: 300px; height: 200px';
    const labels = document.createElement('div');
    document.body.append(canvas, labels);
    const v = new Viewer(canvas, labels);
    /** How much of an image (a data: URL) differs from its first pixel, the background. */
    const pixels = async (/** @type {string} */ src) => {
      const img = new Image();
      img.src = src;
      await img.decode();
      const out = Object.assign(document.createElement('canvas'), { width: img.width, height: img.height });
      const ctx = /** @type {CanvasRenderingContext2D} */ (out.getContext('2d'));
      ctx.drawImage(img, 0, 0);
      return ctx.getImageData(0, 0, img.width, img.height).data;
    };
    const drawn = async (/** @type {string} */ src) => {
      const px = await pixels(src);
      let other = 0;
      for (let i = 0; i < px.length; i += 4) if (px[i] !== px[0] || px[i + 1] !== px[1] || px[i + 2] !== px[2]) other++;
      return other / (px.length / 4);
    };
    try {
      let draws = 0;
      const bind = v.framebuffer.bind.bind(v.framebuffer);
      v.framebuffer.bind = (/** @type {number} */ w, /** @type {number} */ h) => {
        draws++;
        return bind(w, h);
      };
      /** @type {Promise<{draws: number, image: string}>} */
      const first = new Promise((resolve) => {
        v.onFrame = (/** @type {number} */ n) => {
          // (read in the task that drew it: the canvas keeps no frame after it is shown)
          if (n === 1) resolve({ draws, image: canvas.toDataURL() });
        };
      });
      v.show(stage.viewer.built, { fit: true });
      const shown = await first;
      v.onFrame = null;
      v.drawn = '';
      v.render();
      const again = canvas.toDataURL();
      // a size the GPU cannot make a target of is refused, the canvas bound; the viewer then
      // draws straight onto the canvas
      const gl = v.gl;
      const largest = Math.min(gl.getParameter(gl.MAX_RENDERBUFFER_SIZE), ...gl.getParameter(gl.MAX_VIEWPORT_DIMS));
      const counted = draws;
      const refused = v.framebuffer.bind(largest + 1, 4) === false && gl.getParameter(gl.FRAMEBUFFER_BINDING) === null;
      v.framebuffer.bind = () => false;
      v.render();
      const straight = canvas.toDataURL();
      const direct = await drawn(straight);
      // the same picture but for antialiasing: what is hidden stays hidden (the canvas's depth)
      const [a, b] = [await pixels(shown.image), await pixels(straight)];
      let apart = 0;
      for (let i = 0; i < a.length; i += 4)
        if (Math.max(Math.abs(a[i] - b[i]), Math.abs(a[i + 1] - b[i + 1]), Math.abs(a[i + 2] - b[i + 2])) > 64) apart++;
      return {
        before: shown.draws,
        after: counted,
        same: shown.image === again,
        covered: await drawn(shown.image),
        refused,
        direct,
        apart: apart / (a.length / 4),
      };
    } finally {
      v.dispose();
      canvas.remove();
      labels.remove();
    }
  });
  assert.equal(seen.before, 1, 'the figure was drawn into the target once before its first frame');
  assert.equal(seen.after, 2, 'a new frame draws into the target again');
  assert.ok(seen.covered > 0.05, `the first frame shows the figure (${(seen.covered * 100).toFixed(1)} % drawn)`);
  assert.ok(seen.same, 'the first frame shows what a frame drawn anew shows');
  assert.ok(seen.refused, 'a framebuffer larger than the GPU allows was not refused');
  assert.ok(seen.direct > 0.05, `drawn without a target, the figure is not there (${seen.direct})`);
  assert.ok(seen.apart < 0.02, `drawn without a target, ${(seen.apart * 100).toFixed(1)} % of the pixels differ`);
  assert.deepEqual(problems, []);
  await page.close();
});

// The page's first opening goes in steps, its panel's parts invisible in their places until the
// last; a scene opened meanwhile (a click in the menu) ends it, and is what the page shows.
test('an opening in steps ends where another scene is opened meanwhile; the page shows that scene, whole', async () => {
  const page = await browsers.desktop.newPage();
  const problems = watch(page);
  await page.goto(`${url}#scene=striction`);
  await ready(page, 60000);
  const seen = await page.evaluate(async () => {
    const { stage, scenes } = /** @type {any} */ (window).ruledlab;
    const find = (/** @type {string} */ id) => scenes.find((/** @type {any} */ s) => s.id === id);
    const root = stage.els.root;
    /** @type {Promise<unknown> | null} */
    let second = null;
    let hidden = false;
    // as soon as the first opening is in its steps (its controls built, still invisible)
    const watcher = new MutationObserver(() => {
      if (second || !root.classList.contains('rl-opening')) return;
      hidden = getComputedStyle(stage.els.form).visibility === 'hidden';
      // (the second at once, as a click does)
      stage.inSteps = false;
      second = stage.open(find('congruence'), {}, {});
    });
    watcher.observe(root, { attributes: true, attributeFilter: ['class'] });
    stage.inSteps = true;
    // (the first with a camera and a note of its own: neither may reach the scene opened meanwhile)
    const camera = [2.5, 0.7, 9.25, 0.5, -0.25, 0.125];
    const first = stage.open(find('focal'), {}, { camera, notes: [{ key: 'input', note: 'note.badInput' }] });
    await first;
    await second;
    watcher.disconnect();
    return {
      hidden,
      camera: stage.viewer.camera.toArray().join() === camera.join(),
      note: !stage.els.noteBox.hidden,
      interrupted: !!second,
      scene: stage.scene.id,
      opening: root.classList.contains('rl-opening'),
      visible: getComputedStyle(stage.els.form).visibility,
      heading: stage.els.heading.textContent,
      controls: [...stage.els.form.querySelectorAll('[name]')].map((e) => /** @type {HTMLInputElement} */ (e).name),
      params: Object.keys(stage.params).sort(),
      expected: find('congruence')
        .params.map((/** @type {any} */ p) => p.key)
        .sort(),
    };
  });
  assert.ok(seen.interrupted, 'the second opening began while the first was in its steps');
  assert.ok(seen.hidden, 'the panel waited invisible while the first opening was in its steps');
  assert.equal(seen.scene, 'congruence');
  assert.equal(seen.camera, false, 'the ended opening set its camera');
  assert.equal(seen.note, false, 'the ended opening said its note');
  assert.equal(seen.opening, false);
  assert.equal(seen.visible, 'visible');
  assert.match(seen.heading, /Line congruences/);
  assert.deepEqual(seen.params, seen.expected);
  assert.ok(
    seen.controls.every((/** @type {string} */ key) => seen.params.includes(key)),
    `controls of another scene: ${seen.controls}`,
  );
  await ready(page, 60000);
  assert.deepEqual(problems, []);
  await page.close();
});

// An exercise link opens in steps; a scene chosen before its last step is what the page shows —
// the exercise's panel does not come back over it, nothing is held.
test('an exercise opening in steps, ended by a scene chosen meanwhile, leaves no exercise behind', async () => {
  const page = await browsers.desktop.newPage();
  const problems = watch(page);
  await page.addInitScript(() => {
    let done = false;
    new MutationObserver(() => {
      const root = document.querySelector('.rl-stage');
      const ruledlab = /** @type {any} */ (window).ruledlab;
      if (done || !ruledlab || !root?.classList.contains('rl-opening')) return;
      done = true;
      const scene = ruledlab.scenes.find((/** @type {any} */ s) => s.id === 'congruence');
      /** @type {any} */ (window).chosen = ruledlab.stage.open(scene, {}, {});
    }).observe(document, { subtree: true, attributes: true, attributeFilter: ['class'] });
  });
  await page.goto(`${url}#task=chaikin-count&seed=0`);
  await ready(page, 60000);
  await page.evaluate(() => /** @type {any} */ (window).chosen);
  await page.waitForTimeout(300);
  const seen = await page.evaluate(() => {
    const { stage } = /** @type {any} */ (window).ruledlab;
    return {
      chosen: !!(/** @type {any} */ (window).chosen),
      scene: stage.scene.id,
      task: stage.task?.id ?? null,
      panel: !(/** @type {HTMLElement} */ (document.querySelector('.rl-task')).hidden),
      held: [...document.querySelectorAll('.rl-controls [name]')].filter(
        (e) => /** @type {HTMLInputElement} */ (e).disabled,
      ).length,
      classes: /** @type {HTMLElement} */ (document.querySelector('.rl-stage')).className,
    };
  });
  assert.ok(seen.chosen, 'the scene was not chosen while the exercise opened');
  assert.equal(seen.scene, 'congruence');
  assert.equal(seen.task, null);
  assert.equal(seen.panel, false, "the exercise's panel came back");
  assert.doesNotMatch(seen.classes, /rl-opening|rl-waiting/);
  assert.deepEqual(problems, []);
  await page.close();
});
