// The paper's figures and examples as presets, in the browser: each, chosen from the "Figures of
// the paper" menu, draws, shows the paper's caption with ruledlab's notes, has no failing claim,
// and its link restores every control; moving a control marks the change and "Back to …"
// returns; the card speaks German; <ruled-view paper="…"> shows a figure too.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { pageSession, setControl, shoot, ready, framesAfter } from './browser.mjs';
import { countDifferent, decodePng } from './png.mjs';
import { PRESETS } from '../../www/paper.js';

const BACKGROUND = [251, 250, 247];
const session = pageSession();

/** Every control's value, by name. */
/** @param {import('playwright-core').Page} page */
const controls = (page) =>
  page.evaluate(() =>
    Object.fromEntries(
      [...document.querySelectorAll('.rl-controls [name]')].map((e) => {
        const input = /** @type {HTMLInputElement} */ (e);
        return [input.name, input.type === 'checkbox' ? input.checked : input.value];
      }),
    ),
  );

/** Waits for the picture of a new state. @param {import('playwright-core').Page} page @param {() => Promise<unknown>} act */
async function after(page, act) {
  const frames = await page.evaluate(() => Number(document.body.dataset.frames ?? 0));
  await act();
  await ready(page);
  await framesAfter(page, frames);
}

test('every figure and example from the menu: drawn, captioned, its claims hold, its link restores every control', async () => {
  const { page, problems } = await session.open('#scene=striction');
  /** @type {Array<{id: string, hash: string, values: Record<string, unknown>}>} */
  const links = [];
  for (const preset of PRESETS) {
    await after(page, () => page.locator('#paper').selectOption(preset.id));
    const card = page.locator('.rl-paper');
    assert.ok(await card.isVisible(), `${preset.id}: the card is shown`);
    assert.match(await card.locator('h3').innerText(), /Fig\.|Example/);
    assert.equal(await card.locator('.rl-paper-changed').count(), 0, `${preset.id} opens at its own settings`);
    assert.equal(await page.locator('.rl-stage').getAttribute('data-scene'), preset.scene);
    assert.equal(
      await page.locator('.rl-claims .rl-fails').count(),
      0,
      `${preset.id}: a claim fails: ${await page.locator('.rl-claims').innerText()}`,
    );
    const image = decodePng(await page.locator('.rl-view canvas').screenshot());
    assert.ok(countDifferent(image, BACKGROUND) > 0.005 * image.width * image.height, `${preset.id} drew nothing`);
    // what only some figures show: the stencil of (16) beside the view, Fig. 14's notation in it
    const figure = await page.locator('.rl-figure svg title').allTextContents();
    const stencil = preset.params.scheme === 'diagonal' || preset.params.scheme === 'butterfly';
    assert.deepEqual(
      figure,
      stencil ? ['Fig. 12: the butterfly stencil of (16)'] : figure.filter((t) => !/stencil/.test(t)),
      `${preset.id}: the stencil`,
    );
    if (stencil) assert.match((await page.locator('.rl-figure svg').textContent()) ?? '', /\(16\)[\s\S]*1\/8/);
    const labels = await page.locator('.rl-label').allTextContents();
    if (preset.id === 'fig14')
      assert.deepEqual(
        [...labels].sort(),
        ['P i,j', 'R i,j', 'R̄ i,j', 'S i,j', 'T i,j', 'p i+1,j', 'p i+1,j+1', 'p i,j', 'p i,j+1', 'r i,j', 's i,j']
          .map((t) => t.replace(' ', ''))
          .sort(),
        'Fig. 14 names one cell',
      );
    const hash = await page.evaluate(() => location.hash);
    assert.match(hash, new RegExp(`paper=${preset.id}(&|$)`));
    links.push({ id: preset.id, hash, values: await controls(page) });
  }
  // each link, opened after another figure, restores every control
  for (const { id, hash, values } of links) {
    await after(page, () => page.evaluate((h) => (location.hash = h), hash));
    assert.deepEqual(await controls(page), values, `${id}: the link restores every control`);
    assert.equal(await page.locator('#paper').inputValue(), id);
  }
  await shoot(page, 'paper-last');
  assert.deepEqual(problems, []);
  await page.close();
});

test('a moved control is marked as a change from the figure, and "Back to Fig. 3" returns to it', async () => {
  const { page, problems } = await session.open('#paper=fig3');
  assert.match(await page.locator('.rl-paper h3').innerText(), /Fig\. 3/);
  await setControl(page, 'n', 72);
  assert.ok(await page.locator('.rl-paper-changed').isVisible());
  await page.waitForFunction(() => /paper=fig3/.test(location.hash) && /n=72/.test(location.hash));
  // the share dialog's element names the figure and only what differs from it
  await page.locator('#share').click();
  const element = await page.locator('#share-element').inputValue();
  assert.match(element, /<ruled-view scene="striction" paper="fig3" params="n=72" /);
  await page.keyboard.press('Escape');
  await after(page, () => page.locator('.rl-paper-changed button').click());
  assert.equal(await page.locator('.rl-controls [name="n"]').inputValue(), '36');
  assert.ok(
    await page.evaluate(() => document.activeElement?.closest('.rl-controls') !== null),
    'the keyboard stays in the controls',
  );
  assert.equal(await page.locator('.rl-paper-changed').count(), 0);
  // choosing a scene leaves the figure
  await after(page, () => page.locator('#scene').selectOption('curves'));
  assert.ok(await page.locator('.rl-paper').isHidden());
  assert.equal(await page.locator('#paper').inputValue(), '');
  assert.deepEqual(problems, []);
  await page.close();
});

test('the card in German, and <ruled-view paper="fig15">', async () => {
  const { page, problems } = await session.open('#paper=fig5-orthogonal&lang=de');
  const card = await page.locator('.rl-paper').innerText();
  assert.match(card, /Aus der Arbeit: Abb\. 5/);
  assert.match(card, /Über die Arbeit hinaus/);
  assert.match(await page.locator('.rl-claims').innerText(), /Bildunterschrift/);
  await page.evaluate(async () => {
    await import('./www/index.js');
    const view = document.createElement('ruled-view');
    view.setAttribute('paper', 'fig15');
    view.setAttribute('controls', '');
    view.setAttribute('lang', 'en');
    document.body.append(view);
  });
  await page.waitForFunction(() => {
    const v = /** @type {HTMLElement | null} */ (document.querySelector('ruled-view'));
    return v?.dataset.ready === '1' && Number(v.dataset.frames) > 0;
  });
  const inner = await page.evaluate(
    () => document.querySelector('ruled-view')?.shadowRoot?.querySelector('.rl-paper')?.textContent ?? '',
  );
  assert.match(inner, /Fig\. 15/);
  assert.match(inner, /K = 6/);
  assert.deepEqual(problems, []);
  await page.close();
});
