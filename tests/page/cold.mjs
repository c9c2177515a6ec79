// <ruled-view> loaded cold — the first ruledlab code on a page — for every figure of the paper
// and every scene: pages of elements in batches (a page keeps at most 16 WebGL contexts), each
// element required to draw, with no console error and no failed request.
import assert from 'node:assert/strict';
import { PRESETS } from '../../www/paper.js';
import { SCENES } from '../../www/scenes/index.js';
import { watch } from './browser.mjs';
import { decodePng, countDifferent } from './png.mjs';
import { BACKGROUND } from './places.mjs';

/** Every element to try: `paper="…"` for each figure, `scene="…"` for each scene. */
export const ELEMENTS = [...PRESETS.map((p) => `paper="${p.id}"`), ...SCENES.map((s) => `scene="${s.id}"`)];

/**
 * Opens, for each batch of `ELEMENTS`, a page made by `page(elements)` and checks every element.
 * @param {import('playwright-core').BrowserContext} browser
 * @param {(elements: string) => string} write   writes the page's HTML and returns its URL
 * @param {(url: string) => boolean} [ours]      requests that may be made (default: all)
 */
export async function everyElementCold(browser, write, ours = () => true) {
  const BATCH = 13;
  for (let start = 0; start < ELEMENTS.length; start += BATCH) {
    const batch = ELEMENTS.slice(start, start + BATCH);
    const html = batch
      .map(
        (attrs, k) =>
          `<ruled-view id="v${k}" ${attrs} style="display: inline-block; width: 300px; height: 230px"></ruled-view>`,
      )
      .join('\n');
    const page = await browser.newPage({ viewport: { width: 1300, height: 1200 } });
    const problems = watch(page);
    /** @type {string[]} */
    const requests = [];
    page.on('request', (r) => requests.push(r.url()));
    await page.goto(write(html));
    await page
      .waitForFunction(
        (n) => {
          const views = [...document.querySelectorAll('ruled-view')];
          return views.length === n && views.every((v) => v.dataset.ready === '1' && Number(v.dataset.frames) > 0);
        },
        batch.length,
        { timeout: 90000 },
      )
      .catch(async () => {
        const states = await page.evaluate(() =>
          [...document.querySelectorAll('ruled-view')].map(
            (v) =>
              `${v.getAttribute('paper') ?? v.getAttribute('scene')}: ready=${v.dataset.ready} ${v.shadowRoot?.querySelector('.rl-error:not([hidden])')?.textContent ?? ''}`,
          ),
        );
        assert.fail(`not every element drew: ${states.join('; ')}; ${problems.join('; ')}`);
      });
    for (let k = 0; k < batch.length; k++) {
      const image = decodePng(await page.locator(`#v${k}`).screenshot());
      assert.ok(countDifferent(image, BACKGROUND) > 0.01 * image.width * image.height, `${batch[k]} drew nothing`);
    }
    assert.deepEqual(problems, [], batch.join(' '));
    assert.deepEqual(
      requests.filter((u) => !ours(u)),
      [],
      'requests outside ruledlab’s files',
    );
    await page.close();
  }
}
