// Controls that fit any box: <ruled-view controls> as the Share dialog hands it out (560 px
// high) in columns of 280, 390, 700 and 1280 px on a page of another site, and the page on a
// phone. Every control is reached as a reader reaches it — the wheel over the panel, a click, a
// key — inside the element's box, and moves the picture, while the view keeps at least 55 % of
// the height. On a phone every target is at least 44 × 44 CSS px, no text is under 12 px, a
// slider with more values than pixels has − / + steps, and "?" lists the touch gestures first.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { pageSession, launch, watch, ready, shoot, showScene } from './browser.mjs';
import { otherOrigin, hostPage, drawnShare } from './places.mjs';
import { decodePng, countChanged } from './png.mjs';
import { handlesOnPage } from './hands.mjs';

const session = pageSession();
const site = otherOrigin();

/** Geometry of the element, its view, its panel and a control, in page coordinates. */
const boxes = (page, name) =>
  page.locator('ruled-view').evaluate((v, key) => {
    const r = (/** @type {Element | null} */ e) => (e ? e.getBoundingClientRect().toJSON() : null);
    const root = /** @type {ShadowRoot} */ (v.shadowRoot);
    const control = root.querySelector(`.rl-controls [name="${key}"]`);
    const c = r(control);
    const hit = c ? root.elementFromPoint(c.x + c.width / 2, c.y + c.height / 2) : null;
    return {
      element: r(v),
      view: r(root.querySelector('.rl-view')),
      panel: r(root.querySelector('.rl-panel')),
      control: c,
      hit: hit === control,
    };
  }, name);

/** The control's box lies inside the element's box and inside the panel's visible part. */
const inside = (b) =>
  b.control &&
  b.control.y >= Math.max(b.element.y, b.panel.y) - 0.5 &&
  b.control.y + b.control.height <= Math.min(b.element.y + b.element.height, b.panel.y + b.panel.height) + 0.5 &&
  b.control.x >= b.element.x - 0.5 &&
  b.control.x + b.control.width <= b.element.x + b.element.width + 0.5;

for (const width of [280, 390, 700, 1280]) {
  test(`<ruled-view controls> in a ${width}-px column, 560 px high: every control reached inside the element moves the picture; the view keeps ≥ 55 %`, async () => {
    const url = site.write(
      `column-${width}.html`,
      hostPage(
        `<div style="width: ${width}px"><script defer src="${session.url}dist/ruledlab-embed.js"></script>\n<ruled-view paper="fig2" params="" lang="en" controls style="display: block; height: 560px; max-width: 100%"></ruled-view></div>`,
      ),
    );
    const { page, problems } = await session.open(url, { wait: false });
    await page.waitForFunction(() => document.querySelector('ruled-view')?.dataset.ready === '1', null, {
      timeout: 30000,
    });
    const keys = await page
      .locator('ruled-view')
      .evaluate((v) =>
        [...v.shadowRoot.querySelectorAll('.rl-controls [name]')]
          .filter((e) => !e.disabled)
          .map((e) => e.getAttribute('name')),
      );
    assert.ok(keys.length >= 8, `only ${keys.length} controls`);
    const view = () =>
      page
        .locator('ruled-view')
        .evaluate((v) => v.shadowRoot.querySelector('.rl-view canvas').getBoundingClientRect().toJSON());
    const picture = async () => decodePng(await page.screenshot({ clip: await view() }));
    for (const key of keys) {
      // scroll as a reader does: the wheel over the panel, until the control is in sight
      let b = await boxes(page, key);
      for (let k = 0; k < 40 && !inside(b); k++) {
        const panel = b.panel;
        await page.mouse.move(panel.x + panel.width / 2, Math.max(panel.y, b.element.y) + 12);
        await page.mouse.wheel(0, b.control.y > panel.y ? 80 : -80);
        await page.waitForTimeout(50);
        b = await boxes(page, key);
      }
      assert.ok(inside(b), `${width} px: "${key}" cannot be reached inside the element`);
      assert.ok(b.hit, `${width} px: "${key}" is covered where a reader would touch it`);
      assert.ok(
        b.view.height >= 0.55 * b.element.height - 0.5,
        `${width} px: the view keeps only ${((100 * b.view.height) / b.element.height).toFixed(0)} % of the height`,
      );
      const before = await picture();
      const { control } = b;
      const [x, y] = [control.x + control.width / 2, control.y + control.height / 2];
      const type = await page
        .locator('ruled-view')
        .evaluate((v, k) => v.shadowRoot.querySelector(`.rl-controls [name="${k}"]`).type, key);
      if (type === 'checkbox') await page.mouse.click(x, y);
      else if (type === 'range') {
        await page.mouse.click(x, y);
        await page.keyboard.press('ArrowRight');
      } else {
        await page.mouse.click(x, y);
        await page.keyboard.press('ArrowDown');
        await page.keyboard.press('Enter');
      }
      await page.waitForTimeout(350);
      // the renderer is deterministic (an unchanged picture changes no pixel); the smallest real
      // change here is Fig. 2's exact striction curve at 280 px, mostly under the polygon that
      // approximates it (44 pixels), its legend entry being in the panel under the view
      assert.ok(countChanged(before, await picture()) > 30, `${width} px: "${key}" did not change the picture`);
    }
    assert.ok(drawnShare(await page.locator('ruled-view').screenshot()) > 0.02);
    assert.deepEqual(problems, []);
    await page.close();
  });
}

test('the page on a phone: 44-px targets, no text under 12 px, steps for a dense slider, the view in sight while a control is used, touch gestures under "?"', async () => {
  const phone = await launch({ viewport: { width: 390, height: 844 }, isMobile: true, hasTouch: true });
  try {
    const page = await phone.newPage();
    const problems = watch(page);
    await page.goto(`${session.url}#paper=fig2`);
    await ready(page);
    const small = await page.evaluate(() =>
      [...document.querySelectorAll('button, input, select, summary, textarea, a[href]')]
        .filter((e) => e.checkVisibility())
        .map((e) => ({
          what: e.getAttribute('name') || e.className || e.textContent?.trim() || e.tagName,
          ...e.getBoundingClientRect().toJSON(),
        }))
        .filter((r) => r.width < 44 - 0.5 || r.height < 44 - 0.5),
    );
    assert.deepEqual(small, [], 'targets smaller than 44 × 44 CSS px on a touch screen');
    const tiny = await page.evaluate(() => {
      const out = [];
      const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
      for (let n = walker.nextNode(); n; n = walker.nextNode()) {
        const e = n.parentElement;
        if (!e || !n.textContent?.trim() || !e.checkVisibility() || e.closest('.rl-sr-only, option')) continue;
        const size = parseFloat(getComputedStyle(e).fontSize);
        if (size < 12 - 0.01) out.push(`${size.toFixed(1)} px: ${n.textContent.trim().slice(0, 30)}`);
      }
      return out;
    });
    assert.deepEqual(tiny, [], 'text under 12 px');
    // the N slider maps 157 values onto far fewer pixels: − / + and a field reach each one
    const row = page.locator('.rl-row[data-key="n"]');
    assert.ok(await row.locator('.rl-step').first().isVisible(), 'no steps beside the dense slider');
    assert.ok(await row.locator('.rl-exact').isVisible(), 'no number field beside the dense slider');
    // scrolled to the slider, the view stays in sight while the slider is used
    const before = await shoot(page, 'phone-fig2-before');
    await row.locator('.rl-step').last().scrollIntoViewIfNeeded();
    await row.locator('.rl-step').last().tap();
    await page.waitForFunction(
      () => /** @type {HTMLInputElement} */ (document.querySelector('.rl-controls [name="n"]')).value === '37',
    );
    await ready(page);
    const seen = await page.evaluate(() => {
      const v = /** @type {HTMLElement} */ (document.querySelector('.rl-view')).getBoundingClientRect();
      const plus = /** @type {HTMLElement} */ (
        [...document.querySelectorAll('.rl-row[data-key="n"] .rl-step')].at(-1)
      ).getBoundingClientRect();
      const visible = Math.min(v.bottom, innerHeight) - Math.max(v.top, 0);
      const top = document.elementFromPoint(plus.x + plus.width / 2, plus.y + plus.height / 2);
      return { share: visible / innerHeight, reachable: !!top?.closest('.rl-step') };
    });
    assert.ok(
      seen.share >= 0.55,
      `the view keeps only ${(100 * seen.share).toFixed(0)} % of the screen while N is used`,
    );
    assert.ok(seen.reachable, 'the view covers the + button');
    const after = await shoot(page, 'phone-fig2-after');
    assert.ok(countChanged(before, after) > 500, '+ did not change the picture');
    // "?" on a touch screen: the gestures first
    await page.locator('.rl-help').tap();
    assert.match(await page.locator('.rl-shortcuts h2').first().innerText(), /Touch/);
    assert.match(await page.locator('.rl-shortcuts').innerText(), /pinch/);
    // editing on a phone: the toolbar becomes one row of signs (the move modes, ✎, ↶ ↷), low over the figure
    const edit = await phone.newPage();
    const editProblems = watch(edit);
    await edit.goto(`${session.url}#scene=milling`);
    await ready(edit);
    await edit.locator('.rl-edit').tap();
    await edit.locator('.rl-modes').waitFor();
    const bar = await edit.evaluate(() =>
      [...document.querySelectorAll('.rl-bar button')]
        .filter((b) => b.checkVisibility())
        .map((b) => ({ name: b.getAttribute('aria-label') ?? b.textContent, ...b.getBoundingClientRect().toJSON() })),
    );
    assert.ok(bar.length >= 4, `the edit toolbar: ${bar.map((b) => b.name).join(', ')}`);
    assert.ok(
      Math.max(...bar.map((b) => b.top + b.height / 2)) - Math.min(...bar.map((b) => b.top + b.height / 2)) < 4,
      `the edit toolbar on one row: ${JSON.stringify(bar.map((b) => [b.name, Math.round(b.left), Math.round(b.top), Math.round(b.width)]))}`,
    );
    assert.deepEqual(
      bar.filter((b) => b.width < 43.5 || b.height < 43.5).map((b) => b.name),
      [],
      'edit toolbar targets under 44 px',
    );
    // at 360 px, after an edit (↶ ↷ shown): all eight targets still on one row, each 44 px
    await edit.setViewportSize({ width: 360, height: 740 });
    await ready(edit);
    const handle = (await handlesOnPage(edit)).find((h) => h.free);
    assert.ok(handle, 'a handle in sight at 360 px');
    await edit.mouse.move(handle.x, handle.y);
    await edit.mouse.down();
    await edit.mouse.move(handle.x + 12, handle.y + 6, { steps: 4 });
    await edit.mouse.up();
    await edit.locator('.rl-undo:not([hidden])').waitFor();
    const narrow = await edit.evaluate(() =>
      [...document.querySelectorAll('.rl-bar button')]
        .filter((b) => b.checkVisibility())
        .map((b) => ({ name: b.getAttribute('aria-label') ?? b.textContent, ...b.getBoundingClientRect().toJSON() })),
    );
    const rows = new Set(narrow.map((b) => Math.round(b.top)));
    assert.ok(
      narrow.length >= 8 && rows.size === 1,
      `at 360 px: ${JSON.stringify(narrow.map((b) => [b.name, Math.round(b.left), Math.round(b.top)]))}`,
    );
    assert.ok(
      narrow.every((b) => b.width >= 43.5 && b.height >= 43.5 && b.left >= 0 && b.right <= 360),
      'targets of 44 px inside the screen',
    );
    await edit.close();
    // an exercise on a phone: Check brings its verdict into sight
    const task = await phone.newPage();
    const taskProblems = watch(task);
    await task.goto(`${session.url}#task=torsal-pair`);
    await ready(task);
    await task.locator('.rl-task-check').tap();
    const verdict = await task.evaluate(() => {
      const r = /** @type {HTMLElement} */ (document.querySelector('.rl-task-verdict')).getBoundingClientRect();
      return { top: r.top, bottom: r.bottom, height: innerHeight };
    });
    assert.ok(verdict.top >= 0 && verdict.bottom <= verdict.height, `the verdict at ${JSON.stringify(verdict)}`);
    await task.close();
    // a slider whose values lie closer than a finger aims (coupled-strip's n: 22 values) keeps its
    // − / +, and one tap of + reaches the next value
    const coupled = await phone.newPage();
    const coupledProblems = watch(coupled);
    await coupled.goto(`${session.url}#task=coupled-strip`);
    await ready(coupled);
    const n = coupled.locator('.rl-row[data-key="n"]');
    const width = await n.locator('input[type=range]').evaluate((e) => e.getBoundingClientRect().width);
    assert.ok(width < 22 * 8, `the n slider is ${width} px: a finger lands on its values`);
    assert.ok(await n.locator('.rl-step').last().isVisible(), 'no − / + beside n on a phone');
    await n.locator('.rl-step').last().tap();
    await coupled.waitForFunction(
      () => /** @type {HTMLInputElement} */ (document.querySelector('.rl-controls [name="n"]')).value === '4',
    );
    await coupled.close();
    assert.deepEqual([...problems, ...editProblems, ...taskProblems, ...coupledProblems], []);
  } finally {
    await phone.close();
  }
});

test('with a mouse, on every scene of the page and in the element: every target at least 24 × 24 CSS px, no text under 12 px', async () => {
  const { page, problems } = await session.open('');
  const scenes = await page.evaluate(() => window.ruledlab.scenes.map((s) => s.id));
  /** Targets under 24 px and texts under 12 px in `root` (and the shadow roots in it). */
  const audit = () =>
    page.evaluate(() => {
      const out = [];
      const walk = (root) => {
        for (const e of root.querySelectorAll('button, input, select, summary, textarea, a[href]')) {
          if (!e.checkVisibility() || e.closest('.rl-sr-only')) continue;
          const r = e.getBoundingClientRect();
          if (r.width < 24 - 0.5 || r.height < 24 - 0.5)
            out.push(
              `target ${Math.round(r.width)}×${Math.round(r.height)}: ${e.getAttribute('name') || e.className || e.textContent?.trim().slice(0, 30)}`,
            );
        }
        const walker = document.createTreeWalker(root, NodeFilter.SHOW_TEXT);
        for (let n = walker.nextNode(); n; n = walker.nextNode()) {
          const e = n.parentElement;
          if (!e || !n.textContent?.trim() || !e.checkVisibility() || e.closest('.rl-sr-only, option')) continue;
          // in an SVG figure, its user units times the figure's scale on screen
          const svg = e.closest('svg');
          const scale = svg?.viewBox?.baseVal?.width
            ? svg.getBoundingClientRect().width / svg.viewBox.baseVal.width
            : 1;
          const size = parseFloat(getComputedStyle(e).fontSize) * scale;
          if (size < 12 - 0.01) out.push(`text ${size.toFixed(1)} px: ${n.textContent.trim().slice(0, 30)}`);
        }
        for (const host of root.querySelectorAll('*')) if (host.shadowRoot) walk(host.shadowRoot);
      };
      walk(document);
      return out;
    });
  for (const id of scenes) {
    await showScene(page, `#scene=${id}`, id);
    await page.evaluate(() =>
      document.querySelectorAll('details').forEach((d) => {
        d.open = true;
      }),
    );
    assert.deepEqual(await audit(), [], id);
  }
  // and <ruled-view controls> beside the page's own view
  await page.evaluate(async () => {
    await import('/www/index.js');
    const v = Object.assign(document.createElement('ruled-view'), { id: 'mouse' });
    v.setAttribute('paper', 'fig15');
    v.setAttribute('controls', '');
    v.style.cssText = 'display: block; width: 420px; height: 560px';
    document.body.append(v);
  });
  await page.waitForFunction(() => document.getElementById('mouse').dataset.ready === '1');
  assert.deepEqual(await audit(), [], 'with a <ruled-view>');
  assert.deepEqual(problems, []);
  await page.close();
});
