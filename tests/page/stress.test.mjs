// The page under stress and under a strict Content-Security-Policy sent as a header.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { pageSession, shoot, framesAfter, animationFrames, ready, control, showScene } from './browser.mjs';
import { countDifferent } from './png.mjs';

const BACKGROUND = [251, 250, 247];
const CSP =
  "default-src 'self'; script-src 'self' 'wasm-unsafe-eval'; worker-src 'self' blob:; style-src 'self'; img-src 'self' blob: data:; object-src 'none'; base-uri 'none'; frame-ancestors 'self'";
const session = pageSession({ headers: { 'content-security-policy': CSP } });
const open = (hash) => session.open(hash);

test('every scene works under a strict CSP (no inline script or style) and requests nothing but its own files', async () => {
  const origin = new URL(session.url).origin;
  // one page under the policy, walking every scene by its link
  const { page, problems, requests } = await open();
  const scenes = await page.evaluate(() => window.ruledlab.scenes.map((s) => s.id));
  for (const id of scenes) {
    await showScene(page, `#scene=${id}`, id);
    const image = await shoot(page, `csp-${id}`);
    assert.ok(
      countDifferent(image, BACKGROUND) > 0.005 * image.width * image.height,
      `${id} drew nothing under the CSP`,
    );
  }
  await page.close();
  assert.deepEqual(problems, []);
  const all = requests;
  const foreign = all.filter((u) => !u.startsWith(origin) && !u.startsWith('blob:') && !u.startsWith('data:'));
  assert.deepEqual(foreign, [], 'requests outside the page’s own files');
});

test('a storm of resizes and rapid slider input leave the page consistent and error-free', async () => {
  const { page, problems } = await open('#scene=striction');
  for (let k = 0; k < 40; k++)
    await page.setViewportSize({ width: 500 + ((k * 97) % 900), height: 400 + ((k * 53) % 500) });
  await page.setViewportSize({ width: 1200, height: 800 });
  for (let k = 0; k < 60; k++) await control(page, 'n').fill(String(6 + ((k * 37) % 150)), { timeout: 2000 });
  const f = await page.evaluate(() => Number(document.body.dataset.frames));
  await control(page, 'n').fill('77');
  await control(page, 'n').dispatchEvent('change');
  await framesAfter(page, f);
  const size = await page.evaluate(() => {
    const c = document.querySelector('.rl-view canvas');
    return {
      w: c.width,
      h: c.height,
      cw: Math.round(c.clientWidth * devicePixelRatio),
      ch: Math.round(c.clientHeight * devicePixelRatio),
    };
  });
  assert.deepEqual([size.w, size.h], [size.cw, size.ch], 'the canvas follows its size');
  assert.match(await page.locator('.rl-readout').innerText(), /\b77\b/);
  await page.waitForFunction(() => /n=77/.test(location.hash));
  const image = await shoot(page, 'stress-after');
  assert.ok(countDifferent(image, BACKGROUND) > 0.05 * image.width * image.height);
  assert.deepEqual(problems, []);
  await page.close();
});

test('the 1 280 000-ruling link keeps the page answering, finishes, and draws a level of detail', async () => {
  const { page, problems } = await open('#scene=large&n=10000&steps=7');
  const ticks = await animationFrames(page);
  console.log(`# ${ticks} animation frames in 500 ms while 1.28 M rulings are computed`);
  assert.ok(ticks >= 4, `the page froze: ${ticks} frames in 500 ms`);
  await ready(page, 240000);
  const readout = await page.locator('.rl-readout').innerText();
  assert.match(readout, /1[\s,.]?279[\s,.]?873/);
  assert.match(
    await page.locator('.rl-readout-note').innerText(),
    /Level of detail: the strip is drawn through one ruling in 13 /,
  );
  // still answering after it is drawn: orbiting keeps producing frames
  const after = await animationFrames(page);
  assert.ok(after >= 4, `the page is slow after drawing: ${after} frames in 500 ms`);
  const image = await shoot(page, 'large-1280k');
  assert.ok(countDifferent(image, BACKGROUND) > 0.02 * image.width * image.height);
  assert.deepEqual(problems, []);
  await page.close();
});

test('while the camera moves a heavy strip is drawn from its lighter stand-in, in full once it rests', async () => {
  const { page, problems } = await open('#scene=large&n=10000');
  const canvas = page.locator('.rl-view canvas');
  assert.equal(await canvas.getAttribute('data-detail'), 'full');
  await canvas.focus();
  // every detail the canvas shows from the key press on (reading the attribute after a frame
  // raced the rest: on a loaded machine the full frame could already be there)
  await page.evaluate(() => {
    const c = /** @type {HTMLCanvasElement} */ (document.querySelector('.rl-view canvas'));
    const seen = /** @type {string[]} */ ([]);
    new MutationObserver(() => seen.push(c.getAttribute('data-detail') ?? '')).observe(c, {
      attributes: true,
      attributeFilter: ['data-detail'],
    });
    /** @type {any} */ (window).detailsSeen = seen;
  });
  await page.keyboard.press('ArrowLeft');
  await page.waitForFunction(
    () =>
      document.querySelector('.rl-view canvas')?.getAttribute('data-detail') === 'full' &&
      /** @type {any} */ (window).detailsSeen.length >= 2,
    null,
    { timeout: 5000 },
  );
  const seen = await page.evaluate(() => /** @type {any} */ (window).detailsSeen);
  assert.deepEqual(seen.slice(0, 2), ['stand-in', 'full'], 'the stand-in while moving, the full strip at rest');
  // a light scene never switches
  await page.evaluate(() => (location.hash = '#scene=large&n=1000'));
  await page.waitForFunction(() => /1,000|1 000|1000/.test(document.querySelector('.rl-readout')?.textContent ?? ''));
  const f2 = await page.evaluate(() => Number(document.body.dataset.frames));
  await page.keyboard.press('ArrowLeft');
  await framesAfter(page, f2);
  assert.equal(await canvas.getAttribute('data-detail'), 'full');
  assert.deepEqual(problems, []);
  await page.close();
});
