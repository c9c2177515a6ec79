// The ways of embedding ruledlab (examples/): a plain module, <ruled-view> elements with and
// without controls, and the page in an iframe with #embed&controls.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, writeFileSync } from 'node:fs';
import { pageSession, ARTIFACTS } from './browser.mjs';
import { decodePng, countDifferent, countChanged } from './png.mjs';

const BACKGROUND = [251, 250, 247];
const session = pageSession();

async function grab(locator, name) {
  const png = await locator.screenshot();
  mkdirSync(ARTIFACTS, { recursive: true });
  writeFileSync(`${ARTIFACTS}/${name}.png`, png);
  return decodePng(png);
}

/** Waits until every <ruled-view> of the page has drawn its scene. */
const allDrawn = (page) =>
  page.waitForFunction(
    () =>
      [...document.querySelectorAll('ruled-view')].every(
        (v) => v.dataset.ready === '1' && Number(v.dataset.frames) > 0,
      ),
    null,
    { timeout: 20000 },
  );

test('examples/plain-module.html computes with the package directly', async () => {
  const { page, problems } = await session.open('examples/plain-module.html', { wait: false });
  await page.waitForFunction(() => document.body.dataset.ready === '1');
  assert.equal(await page.locator('#table tbody tr').count(), 6);
  assert.match(await page.locator('#table tbody tr').first().innerText(), /^1\s+\(/);
  assert.deepEqual(problems, []);
  await page.close();
});

test('<ruled-view> elements draw independently; `controls` shows the scene’s controls, which work', async () => {
  const { page, problems } = await session.open('examples/web-component.html', { wait: false });
  await allDrawn(page);
  const [left, right] = [
    await grab(page.locator('#left'), 'component-left'),
    await grab(page.locator('#right'), 'component-right'),
  ];
  for (const image of [left, right]) assert.ok(countDifferent(image, BACKGROUND) > 0.02 * image.width * image.height);
  // the left one has its controls, the right one none
  const sliders = (id) =>
    page
      .locator(`#${id}`)
      .evaluate(
        (v) => [...v.shadowRoot.querySelectorAll('.rl-controls input')].filter((e) => e.checkVisibility()).length,
      );
  assert.ok((await sliders('left')) >= 3, 'the element with `controls` shows its sliders');
  assert.equal(await sliders('right'), 0);
  // a slider inside the element changes its picture and fires scene-change
  const detail = page.evaluate(
    () =>
      new Promise((resolve) =>
        document.getElementById('left').addEventListener('scene-change', (e) => resolve(e.detail), { once: true }),
      ),
  );
  await page.locator('#left').evaluate((v) => {
    const t = v.shadowRoot.querySelector('.rl-controls [name="t"]');
    t.value = '0.8';
    t.dispatchEvent(new Event('input', { bubbles: true }));
    t.dispatchEvent(new Event('change', { bubbles: true }));
  });
  assert.equal((await detail).params.t, 0.8);
  await page.waitForTimeout(200);
  assert.ok(countChanged(left, await grab(page.locator('#left'), 'component-left-moved')) > 1000);
  // an attribute change rebuilds that element only
  const changed = page.evaluate(
    () =>
      new Promise((resolve) =>
        document.getElementById('right').addEventListener('scene-change', (e) => resolve(e.detail), { once: true }),
      ),
  );
  await page.evaluate(() => (document.getElementById('right').params = 'surface=quartic&t=0.5'));
  const got = await changed;
  assert.equal(got.scene, 'isometry');
  assert.equal(got.params.surface, 'quartic');
  assert.equal(got.params.t, 0.5);
  // data as a property shows those rulings
  await page.evaluate(
    () =>
      (document.getElementById('right').data = {
        segments: new Float64Array([0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1, 1, 0, 0, 2, -1, 0, 2]),
      }),
  );
  await page.waitForFunction(() => document.getElementById('right').view?.scene?.id === 'data');
  assert.equal(await page.locator('#right').getAttribute('scene'), 'data');
  // an unknown scene is shown inside the element and fires `error`, nothing is thrown
  const error = page.evaluate(
    () =>
      new Promise((resolve) =>
        document.getElementById('right').addEventListener('error', (e) => resolve(e.detail), { once: true }),
      ),
  );
  await page.evaluate(() => (document.getElementById('right').scene = 'nope'));
  assert.match((await error).message, /There is no scene “nope”/);
  assert.match(
    await page.locator('#right').evaluate((v) => v.shadowRoot.querySelector('.rl-error').textContent),
    /There is no scene “nope”/,
  );
  assert.deepEqual(problems, []);
  await page.close();
});

test('a removed <ruled-view> gives back its WebGL context and every wasm object it made', async () => {
  const { page, problems } = await session.open('examples/web-component.html', { wait: false });
  await allDrawn(page);
  const live = () => page.evaluate(async () => (await import('../pkg/ruledlab.js')).liveObjects());
  const before = await live();
  const result = await page.evaluate(async () => {
    const v = document.createElement('ruled-view');
    v.setAttribute('scene', 'milling');
    v.setAttribute('controls', '');
    document.body.append(v);
    await new Promise((resolve) => v.addEventListener('scene-change', resolve, { once: true }));
    const canvas = v.shadowRoot.querySelector('canvas');
    const gl = canvas.getContext('webgl2');
    v.remove();
    await new Promise((r) => setTimeout(r, 50));
    return { lost: gl.isContextLost(), children: v.shadowRoot.querySelector('.rl-host').children.length };
  });
  assert.equal(result.lost, true, 'the WebGL context was not released');
  assert.equal(result.children, 0);
  assert.equal(await live(), before, 'wasm objects were left behind');
  assert.deepEqual(problems, []);
  await page.close();
});

test('the page in an iframe with #embed&controls shows the view with its controls, without the page around it', async () => {
  const { page, problems } = await session.open('examples/iframe.html', { wait: false });
  const frame = page.frameLocator('#frame');
  await frame.locator('.rl-stage[data-ready="1"]').waitFor({ timeout: 20000 });
  assert.equal(await frame.locator('.page-header').isHidden(), true);
  assert.equal(await frame.locator('.rl-controls').isVisible(), true);
  assert.equal(await frame.locator('.rl-text').isHidden(), true, 'the explanation only with &text');
  const image = await grab(page.locator('#frame'), 'iframe-embed');
  assert.ok(countDifferent(image, BACKGROUND) > 0.02 * image.width * image.height);
  assert.deepEqual(problems, []);
  await page.close();
});

test('<ruled-view> setParams() sets named parameters as the controls would, keeping the camera; readouts() reads the readout', async () => {
  const { page, problems } = await session.open('examples/web-component.html', { wait: false });
  await allDrawn(page);
  const left = page.locator('#left');
  // a camera the reader chose (the fitted one is fitted again when the view's size changes)
  await left.evaluate((v) => (v.camera = '0.3,0.4,12,0,0,0.5'));
  const camera = await left.evaluate((v) => v.camera);
  await page.waitForTimeout(200);
  const before = await grab(left, 'set-params-before');
  const now = await left.evaluate((v) => v.setParams({ t: 0.6, n: 30 }));
  assert.deepEqual([now.t, now.n, now.surface], [0.6, 30, 'helical']);
  assert.equal(await left.evaluate((v) => v.shadowRoot.querySelector('.rl-controls [name="t"]').value), '0.6');
  assert.equal(await left.evaluate((v) => v.camera), camera, 'the camera stays');
  await page.waitForTimeout(200);
  assert.ok(countChanged(before, await grab(left, 'set-params-after')) > 1000);
  // the readout as shown: every label's text, a value each
  const readouts = await left.evaluate((v) => v.readouts());
  const shown = await left.evaluate((v) => v.shadowRoot.querySelector('.rl-readout').textContent);
  assert.ok(readouts.length > 0);
  for (const r of readouts) {
    assert.match(r.key, /^[a-z]+(\.[A-Za-z0-9]+)+$/);
    assert.ok(shown.includes(r.label), `“${r.label}” is in the readout`);
    assert.ok(typeof r.value === 'number' || typeof r.value === 'string');
  }
  // a value it cannot take and a name it has no parameter of: an error event each, in words
  const errors = await left.evaluate((v) => {
    const seen = [];
    v.addEventListener('error', (e) => seen.push(e.detail));
    v.setParams('t=abc&zz=1');
    return seen;
  });
  assert.deepEqual(
    errors.map((e) => [e.code, e.details.param]),
    [
      ['invalid-argument', 't'],
      ['invalid-argument', 'zz'],
    ],
  );
  // said as given to setParams, not as the params attribute
  assert.match(errors[0].message, /^The value setParams was given for “t” is not a number/);
  assert.deepEqual(
    errors.map((e) => e.details.reason),
    ['element.set.notNumber', 'element.set.unknownParam'],
  );
  assert.match(errors[1].message, /no parameter “zz”; its parameters are: surface, layout, n, t, ghost/);
  assert.equal(await left.evaluate((v) => v.view.params.n), 30, 'the others stay');
  // a label with subscripts reads as the page shows it, lowered (a notebook prints these)
  const labels = await left.evaluate(
    (v) =>
      new Promise((done) => {
        v.addEventListener('scene-change', () => done(v.readouts().map((/** @type {any} */ r) => r.label)), {
          once: true,
        });
        v.setAttribute('scene', 'striction');
      }),
  );
  assert.ok(labels.includes('max |mᵢ − s(uᵢ)|'), labels.join(' / '));
  assert.deepEqual(problems, []);
  await page.close();
});
