// The three ways of embedding ruledlab (examples/): a plain module, two <ruled-view>
// elements on one page, and the page in an iframe with #embed.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { pageSession } from './browser.mjs';
import { decodePng, countDifferent, countChanged } from './png.mjs';
import { mkdirSync, writeFileSync } from 'node:fs';
import { ARTIFACTS } from './browser.mjs';

const BACKGROUND = [251, 250, 247];
const session = pageSession();

async function grab(locator, name) {
  const png = await locator.screenshot();
  mkdirSync(ARTIFACTS, { recursive: true });
  writeFileSync(`${ARTIFACTS}/${name}.png`, png);
  return decodePng(png);
}

test('examples/plain-module.html computes with the package directly', async () => {
  const { page, problems } = await session.open('examples/plain-module.html', { wait: false });
  await page.waitForFunction(() => document.body.dataset.ready === '1');
  assert.equal(await page.locator('#table tbody tr').count(), 6);
  assert.match(await page.locator('#table tbody tr').first().innerText(), /^1\s+\(/);
  assert.deepEqual(problems, []);
  await page.close();
});

test('two <ruled-view> elements on one page draw independently and announce changes', async () => {
  const { page, problems } = await session.open('examples/web-component.html', { wait: false });
  await page.waitForFunction(() => [...document.querySelectorAll('ruled-view')].every((v) => Number(v.dataset.frames) > 0));
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  const [left, right] = [await grab(page.locator('#left'), 'component-left'), await grab(page.locator('#right'), 'component-right')];
  for (const image of [left, right]) assert.ok(countDifferent(image, BACKGROUND) > 0.02 * image.width * image.height);
  assert.ok(countChanged(left, right) > 1000, 'the two views show different things');
  // changing an attribute rebuilds that element only, and says so
  const detail = await page.evaluate(
    () => new Promise((resolve) => {
      const v = document.getElementById('left');
      v.addEventListener('scene-change', (e) => resolve(e.detail), { once: true });
      v.params = 'surface=quartic&t=0.5';
    }),
  );
  assert.equal(detail.scene, 'isometry');
  assert.equal(detail.params.surface, 'quartic');
  assert.equal(detail.params.t, 0.5);
  // data as a property: the element shows those rulings
  const frames = await page.evaluate(() => Number(document.getElementById('right').dataset.frames));
  await page.evaluate(() => {
    document.getElementById('right').data = { segments: new Float64Array([0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1, 1, 0, 0, 2, -1, 0, 2]) };
  });
  await page.waitForFunction((n) => Number(document.getElementById('right').dataset.frames) > n, frames);
  assert.equal(await page.locator('#right').getAttribute('scene'), 'data');
  const shown = await grab(page.locator('#right'), 'component-data');
  assert.ok(countDifferent(shown, BACKGROUND) > 0.01 * shown.width * shown.height);
  // an unknown scene is shown as an error inside the element, not thrown
  await page.evaluate(() => (document.getElementById('right').scene = 'nope'));
  assert.match(await page.locator('#right').evaluate((v) => v.shadowRoot.querySelector('.error').textContent), /unknown scene "nope"/);
  assert.deepEqual(problems, []);
  await page.close();
});

test('the page embedded in an iframe with #embed shows the view alone', async () => {
  const { page, problems } = await session.open('examples/iframe.html', { wait: false });
  const frame = page.frameLocator('#frame');
  await frame.locator('body').evaluate((b) => new Promise((resolve) => {
    const check = () => (Number(b.dataset.frames) > 0 ? resolve() : setTimeout(check, 50));
    check();
  }));
  assert.equal(await frame.locator('header').isHidden(), true);
  assert.equal(await frame.locator('.panel').isHidden(), true);
  const image = await grab(page.locator('#frame'), 'iframe-embed');
  assert.ok(countDifferent(image, BACKGROUND) > 0.02 * image.width * image.height);
  assert.deepEqual(problems, []);
  await page.close();
});
