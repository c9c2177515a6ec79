// Accessible in fact: colours that stay apart for colour-blind readers (simulated), axe-core at
// zero WCAG 2.2 A/AA violations on every scene and embed, everything by keyboard with a visible
// focus, a description of every scene linked to the view — what it shows and its key values, in
// both languages, following the figure, said when a new figure opens — and readouts announced only
// when an interaction ends, at most once a second.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { launch, pageSession, ready, shoot, framesAfter, control, showScene, watch } from './browser.mjs';
import { difference, parseColour } from './colour.mjs';
import { countChanged } from './png.mjs';

const AXE = readFileSync(createRequire(import.meta.url).resolve('axe-core/axe.min.js'), 'utf8');
const session = pageSession();
const DEFICIENCIES = [null, 'deuteranopia', 'protanopia', 'tritanopia'];

/** Turns on every checkbox of the panel (every legend entry visible). */
const allOn = (page) =>
  page.evaluate(() => {
    for (const box of document.querySelectorAll('.rl-controls input[type=checkbox]'))
      if (!box.checked && !box.disabled) box.click();
  });

test('every pair of legend colours shown together stays ≥ 15 ΔE00 apart under each colour-vision deficiency', async () => {
  const first = await session.open();
  const scenes = await first.page.evaluate(() => window.ruledlab.scenes.map((s) => s.id));
  await first.page.close();
  const report = [];
  const { page } = await session.open(`#scene=${scenes[0]}`);
  for (const id of scenes) {
    await showScene(page, `#scene=${id}`, id);
    await allOn(page);
    await ready(page);
    const legend = await page.evaluate(() =>
      [...document.querySelectorAll('.rl-legend li')].map((li) => ({
        name: li.textContent,
        color: li.querySelector('svg').dataset.color,
      })),
    );
    let worst = Infinity;
    for (let i = 0; i < legend.length; i++) {
      for (let j = i + 1; j < legend.length; j++) {
        const [a, b] = [legend[i], legend[j]];
        for (const d of DEFICIENCIES) {
          const e = difference(parseColour(a.color), parseColour(b.color), d);
          worst = Math.min(worst, e);
          assert.ok(
            e >= 15,
            `${id}: "${a.name}" and "${b.name}" are only ${e.toFixed(1)} apart under ${d ?? 'normal vision'}`,
          );
        }
      }
    }
    report.push(`${id} ${worst.toFixed(1)}`);
  }
  await page.close();
  console.log(`# smallest ΔE00 per scene: ${report.join(', ')}`);
});

test('axe-core finds no WCAG 2.2 A/AA violation on any scene, in either language, nor on the embeds', async () => {
  const first = await session.open();
  const scenes = await first.page.evaluate(() => window.ruledlab.scenes.map((s) => s.id));
  await first.page.close();
  const run = async (page, what) => {
    await page.evaluate(AXE);
    const result = await page.evaluate(() =>
      window.axe.run(document, {
        runOnly: { type: 'tag', values: ['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa', 'wcag22a', 'wcag22aa'] },
      }),
    );
    const violations = result.violations.map((v) => `${v.id}: ${v.nodes.map((n) => n.target.join(' ')).join(', ')}`);
    assert.deepEqual(violations, [], `${what}`);
  };
  // one page per language, the scenes opened by their links (as a reader following them would)
  for (const lang of ['en', 'de']) {
    const { page } = await session.open(`#scene=${scenes[0]}&lang=${lang}`);
    await page.locator('.io summary').click();
    for (const id of scenes) {
      await showScene(page, `#scene=${id}&lang=${lang}`, id);
      await run(page, `${id} (${lang})`);
    }
    await page.close();
  }
  for (const path of [
    'examples/web-component.html',
    'examples/iframe.html',
    'index.html#embed&controls&text&scene=strip',
  ]) {
    const { page } = await session.open(path, { wait: false });
    await page.waitForTimeout(2500);
    await run(page, path);
    await page.close();
  }
});

test('by keyboard: Tab reaches the view, which shows its focus; arrows turn it; ? lists the keys; controls work', async () => {
  const { page, problems, frames } = await session.open('#scene=isometry');
  const before = await shoot(page, 'keyboard-before');
  await page.locator('.rl-view canvas').focus();
  assert.equal(await page.evaluate(() => document.activeElement.tagName), 'CANVAS');
  assert.equal(await page.evaluate(() => document.querySelector('.rl-view canvas').matches(':focus-visible')), true);
  // the focus ring is drawn over the picture, in the focus colour
  const ring = await page.evaluate(() => getComputedStyle(document.querySelector('.rl-view canvas')).outlineStyle);
  assert.equal(ring, 'solid');
  await page.keyboard.press('ArrowLeft');
  await page.keyboard.press('ArrowLeft');
  await framesAfter(page, frames);
  const turned = await shoot(page, 'keyboard-after');
  assert.ok(countChanged(before, turned) > 1000, 'the arrow keys did not turn the view');
  await page.keyboard.press('?');
  assert.equal(await page.locator('.rl-shortcuts').isVisible(), true);
  assert.match(await page.locator('.rl-shortcuts').innerText(), /turn the view/);
  await page.keyboard.press('Escape');
  assert.equal(await page.locator('.rl-shortcuts').isVisible(), false);
  // Tab onward reaches the controls; arrow keys move a slider
  await control(page, 'n').focus();
  const n = Number(await control(page, 'n').inputValue());
  await page.keyboard.press('ArrowRight');
  await page.waitForFunction((v) => window.ruledlab.stage.params.n === v + 1, n);
  // keys of the view act only while it has focus: F on a slider does not refit
  assert.deepEqual(problems, []);
  await page.close();
});

test('every scene describes itself to screen readers; readouts are announced once an interaction ends, never per frame', async () => {
  const { page, problems } = await session.open('#scene=striction');
  const described = await page.evaluate(() => {
    const canvas = document.querySelector('.rl-view canvas');
    return document.getElementById(canvas.getAttribute('aria-describedby'))?.textContent ?? '';
  });
  assert.match(described, /Hyperboloid.*36 rulings.*striction polygon is/);
  // the view takes keys: an application to a screen reader (which passes it the keys), named as a 3D view
  const canvas = page.locator('.rl-view canvas');
  assert.deepEqual(
    [await canvas.getAttribute('role'), await canvas.getAttribute('aria-roledescription')],
    ['application', '3D view'],
  );
  // Full screen is a toggle that says whether it is on
  const full = page.locator('.rl-fullscreen');
  assert.equal(await full.getAttribute('aria-pressed'), 'false');
  await full.click();
  await page.waitForFunction(() => document.querySelector('.rl-fullscreen')?.getAttribute('aria-pressed') === 'true');
  await full.click();
  await page.waitForFunction(() => document.querySelector('.rl-fullscreen')?.getAttribute('aria-pressed') === 'false');
  // the units menu of the import is named by more than its label "in"
  assert.equal(await page.locator('#import-units').getAttribute('aria-label'), 'in: the units of the tool poses');
  // each language's name is read in that language
  assert.deepEqual(
    await page.evaluate(() => [...document.querySelectorAll('#lang option')].map((o) => [o.value, o.lang])),
    [
      ['en', 'en'],
      ['de', 'de'],
    ],
  );
  // announcements: count changes of the live region while a parameter plays for 2 s
  await page.evaluate(() => {
    window.__announced = 0;
    new MutationObserver(() => window.__announced++).observe(document.querySelector('.rl-stage [aria-live]'), {
      childList: true,
      characterData: true,
      subtree: true,
    });
  });
  await page.locator('.rl-row[data-key="n"] .rl-play').click();
  await page.waitForTimeout(2000);
  assert.equal(await page.evaluate(() => window.__announced), 0, 'the readout was announced while playing');
  await page.locator('.rl-row[data-key="n"] .rl-play').click();
  await page.waitForTimeout(1200);
  assert.equal(await page.evaluate(() => window.__announced), 1, 'pausing announces the readout once');
  const said = await page.evaluate(() => document.querySelector('.rl-stage [aria-live]').textContent);
  assert.match(said, /rulings N: \d+; .*max \|mᵢ − s\(uᵢ\)\|/);
  // ten slider moves in quick succession (in one task of the page, so that a loaded machine
  // cannot spread them out): at most one announcement now and one per second after
  const spent = await control(page, 'n').evaluate((el) => {
    const t0 = performance.now();
    for (let k = 0; k < 10; k++) {
      /** @type {HTMLInputElement} */ (el).value = String(20 + k);
      el.dispatchEvent(new Event('input', { bubbles: true }));
      el.dispatchEvent(new Event('change', { bubbles: true }));
    }
    return performance.now() - t0;
  });
  await page.waitForTimeout(1500);
  const count = await page.evaluate(() => window.__announced);
  assert.ok(
    count >= 2 && count - 1 <= 2 + Math.floor(spent / 1000),
    `${count - 1} announcements for ten quick moves in ${spent.toFixed(0)} ms`,
  );
  // what changes no number is not said again: the view turned and zoomed by keys, the same value
  // set again
  await page.waitForTimeout(1100);
  const before = await page.evaluate(() => window.__announced);
  await page.locator('.rl-view canvas').focus();
  for (const key of ['ArrowLeft', 'ArrowLeft', 'ArrowUp', '+', 'f']) await page.keyboard.press(key);
  await page.waitForTimeout(1200);
  await control(page, 'n').evaluate((el) => el.dispatchEvent(new Event('change', { bubbles: true })));
  await page.waitForTimeout(1200);
  assert.equal(await page.evaluate(() => window.__announced), before, 'a step that changed no number was said');
  assert.deepEqual(problems, []);
  await page.close();
});

test('every scene describes what it shows with its key values, in English and in German; the description follows the figure and a new figure is said', async () => {
  const first = await session.open();
  const scenes = await first.page.evaluate(() =>
    window.ruledlab.scenes.map((s) => ({
      id: s.id,
      // the number of rulings where a scene has it, else its first slider
      range: s.params.find((p) => p.key === 'n')?.key ?? s.params.find((p) => p.type === 'range')?.key,
    })),
  );
  await first.page.close();
  /** @type {Record<string, Record<string, string>>} */
  const said = { en: {}, de: {} };
  for (const lang of ['en', 'de']) {
    const { page, problems } = await session.open(`#scene=${scenes[0].id}&lang=${lang}`);
    const description = () =>
      page.evaluate(() => {
        const canvas = document.querySelector('.rl-view canvas');
        return document.getElementById(canvas.getAttribute('aria-describedby'))?.textContent ?? '';
      });
    for (const { id, range } of scenes) {
      await showScene(page, `#scene=${id}&lang=${lang}`, id);
      const text = await description();
      said[lang][id] = text;
      assert.ok(text.length > 40, `${id} (${lang}): "${text}"`);
      assert.match(text, /\d/, `${id} (${lang}) says no value: "${text}"`);
      // a new figure is said to screen readers (politely)
      const spoken = await page.evaluate(() => document.querySelector('.rl-stage [aria-live]')?.textContent ?? '');
      // (the live region is plain text: a subscript in Unicode's characters, m₁₈ for m<sub>18</sub>)
      const lowered = '₀₁₂₃₄₅₆₇₈₉₊₋₌₍₎ₐₑₕᵢⱼₖₗₘₙₒₚᵣₛₜᵤᵥₓ';
      const base = '0123456789+−=()aehijklmnoprstuvx';
      const plain = spoken.replace(/./gu, (c) => (lowered.includes(c) ? base[[...lowered].indexOf(c)] : c));
      assert.equal(plain.replace(/\s/g, ''), text.replace(/\s/g, ''), `${id} (${lang}) was not said`);
      // the description follows the figure: another value of a slider says another thing
      if (range) {
        const value = await page.evaluate((key) => {
          const p = window.ruledlab.stage.scene.params.find((q) => q.key === key);
          const now = Number(window.ruledlab.stage.params[key]);
          return now + (now + (p.step ?? 1) <= p.max ? 1 : -1) * (p.step ?? (p.max - p.min) / 10);
        }, range);
        await page.evaluate(([key, v]) => window.ruledlab.stage.setParam(key, v), [range, value]);
        await ready(page, 60000);
        if (!['large'].includes(id))
          assert.notEqual(await description(), text, `${id} (${lang}): ${range} moved, the same words`);
      }
    }
    assert.deepEqual(problems, []);
    await page.close();
  }
  for (const { id } of scenes) assert.notEqual(said.en[id], said.de[id], `${id}: the same words in both languages`);
});

test('reflow at 320 px: no scene scrolls sideways (a plot or a formula wider than that scrolls in its own box); focus is never hidden under the view', async () => {
  const narrow = await launch({ viewport: { width: 320, height: 640 } });
  try {
    const page = await narrow.newPage();
    const problems = watch(page);
    await page.goto(`${session.url}#scene=striction`);
    await ready(page);
    const scenes = await page.evaluate(() => window.ruledlab.scenes.map((s) => s.id));
    for (const id of scenes) {
      await showScene(page, `#scene=${id}`, id);
      const wide = await page.evaluate(() => {
        // what reaches past the screen's right edge, unless a box that scrolls holds it
        const scrolls = (/** @type {Element} */ e) => {
          for (let a = e.parentElement; a; a = a.parentElement)
            if (
              ['auto', 'scroll'].includes(getComputedStyle(a).overflowX) &&
              a.getBoundingClientRect().right <= innerWidth + 1
            )
              return true;
          return false;
        };
        return {
          page: document.documentElement.scrollWidth,
          out: [...document.querySelectorAll('body *')]
            .filter(
              (e) =>
                e.checkVisibility() &&
                !e.closest('.rl-sr-only') &&
                e.getBoundingClientRect().right > innerWidth + 1 &&
                !scrolls(e),
            )
            .map((e) => `${e.tagName.toLowerCase()}.${e.getAttribute('class') ?? ''}`)
            .slice(0, 5),
        };
      });
      assert.equal(wide.page, 320, `${id}: the page scrolls sideways`);
      assert.deepEqual(wide.out, [], `${id}: cut off at 320 px`);
    }
    // 2.4.11: every control the keyboard reaches shows at least in part beside the sticky view
    await showScene(page, '#scene=striction', 'striction');
    await page.focus('.rl-view canvas');
    const hidden = [];
    for (let k = 0; k < 40; k++) {
      await page.keyboard.press('Tab');
      const seen = await page.evaluate(() => {
        const e = /** @type {HTMLElement} */ (document.activeElement);
        if (!e || e === document.body) return null;
        const r = e.getBoundingClientRect();
        const v = /** @type {HTMLElement} */ (document.querySelector('.rl-view')).getBoundingClientRect();
        // on screen, less what the view covers of it (nothing of what is in the view itself)
        const [top, bottom] = [Math.max(r.top, 0), Math.min(r.bottom, innerHeight)];
        const covered = e.closest('.rl-view') ? 0 : Math.max(0, Math.min(bottom, v.bottom) - Math.max(top, v.top));
        return { what: e.getAttribute('name') || e.className || e.tagName, visible: bottom - top - covered > 0 };
      });
      if (seen && !seen.visible) hidden.push(seen.what);
    }
    assert.deepEqual(hidden, [], 'focused controls hidden under the view');
    assert.deepEqual(problems, []);
  } finally {
    await narrow.close();
  }
});

test('stepping through the closed scene menu with the arrow keys opens only the scene the steps end on; Enter opens it at once', async () => {
  const { page, problems } = await session.open('#scene=striction');
  const ids = await page.evaluate(() => [...document.querySelectorAll('#scene option')].map((o) => o.value));
  const start = ids.indexOf('striction');
  await page.evaluate(() => {
    window.__scenes = [];
    const root = /** @type {HTMLElement} */ (document.querySelector('.rl-stage'));
    new MutationObserver(() => window.__scenes.push(root.dataset.scene)).observe(root, {
      attributes: true,
      attributeFilter: ['data-scene'],
    });
  });
  await page.locator('#scene').focus();
  for (let k = 0; k < 3; k++) await page.keyboard.press('ArrowDown');
  assert.equal(await page.evaluate(() => window.ruledlab.stage.scene.id), 'striction', 'a step opened a scene');
  await page.locator(`.rl-stage[data-scene="${ids[start + 3]}"][data-ready="1"]`).waitFor({ timeout: 30000 });
  assert.deepEqual(await page.evaluate(() => window.__scenes), [ids[start + 3]], 'the scenes on the way were opened');
  // one step and Enter: at once
  await page.keyboard.press('ArrowDown');
  await page.keyboard.press('Enter');
  assert.equal(await page.evaluate(() => window.ruledlab.stage.scene.id), ids[start + 4]);
  assert.equal(await page.evaluate(() => document.activeElement?.id), 'scene', 'the keyboard stayed on the menu');
  assert.deepEqual(problems, []);
  await page.close();
});

// A display equation that scrolls sideways takes the keyboard (it can be scrolled by keys); one
// that fits its column is no tab stop to pass — on a phone at 320 px and on a desktop alike.
test('display equations are tab stops exactly where they scroll sideways (320 px and desktop)', async () => {
  /** @type {Record<string, {scrolls: number, fits: number}>} */
  const counted = {};
  for (const [name, viewport] of /** @type {const} */ ([
    ['phone', { width: 320, height: 640 }],
    ['desktop', { width: 1350, height: 940 }],
  ])) {
    const browser = await launch({ viewport });
    try {
      const page = await browser.newPage();
      const problems = watch(page);
      counted[name] = { scrolls: 0, fits: 0 };
      for (const scene of ['curves', 'striction', 'strip', 'congruence']) {
        await page.goto(`${session.url}#scene=${scene}`);
        await ready(page);
        const seen = await page.evaluate(async () => {
          const maths = [
            .../** @type {NodeListOf<HTMLElement>} */ (document.querySelectorAll('.rl-text math[display="block"]')),
          ];
          const frame = () => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
          const out = [];
          for (const math of maths) {
            math.scrollIntoView({ block: 'center' });
            await frame();
            out.push({
              scrolls: math.scrollWidth > math.clientWidth + 1,
              stop: math.getAttribute('tabindex') === '0',
            });
          }
          return out;
        });
        for (const [k, { scrolls, stop }] of seen.entries()) {
          assert.equal(stop, scrolls, `${name} ${scene}, equation ${k + 1}: ${scrolls ? 'scrolls' : 'fits'}`);
          counted[name][scrolls ? 'scrolls' : 'fits']++;
        }
      }
      assert.deepEqual(problems, []);
    } finally {
      await browser.close();
    }
  }
  // (both cases met: the test is not empty on either side)
  assert.ok(counted.phone.scrolls > 0, `at 320 px no equation scrolls: ${JSON.stringify(counted)}`);
  assert.ok(counted.desktop.fits > 0, `on a desktop every equation scrolls: ${JSON.stringify(counted)}`);
});
