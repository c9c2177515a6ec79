// The milling scene with a real machine, in headless Chromium: the deviation along the path as a
// plot, the G-code for the machine, controller and mode chosen in the page, and the engineer's own
// tool poses imported — ruledlab's own CSV and JSON exports recognised as tool poses and round
// tripping (the same poses, the same tool, a link that restores them), a plain CSV of tip and
// axis chosen explicitly as tool poses.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import ruledlab from '../node/load.mjs';
import { pageSession, ready, setControl, showScene } from './browser.mjs';

const session = pageSession();
const { ToolPath } = ruledlab;

/** The text of the download whose button says `label`. */
async function downloaded(/** @type {import('playwright-core').Page} */ page, /** @type {RegExp} */ label) {
  const [file] = await Promise.all([
    page.waitForEvent('download'),
    page.locator('.rl-downloads button', { hasText: label }).click(),
  ]);
  return { name: file.suggestedFilename(), text: readFileSync(/** @type {string} */ (await file.path()), 'utf8') };
}

/** Pastes `text` into the import box with the kind `kind` and shows it. */
async function paste(/** @type {import('playwright-core').Page} */ page, /** @type {string} */ text, kind = 'auto') {
  if (!(await page.locator('#import-text').isVisible())) await page.locator('.io summary').click();
  await page.locator('#import-kind').selectOption(kind);
  await page.locator('#import-text').fill(text);
  await page.locator('#import-button').click();
}

test('the milling scene plots the deviation along the path and writes G-code for the machine chosen', async () => {
  const { page, problems } = await session.open('#scene=milling');
  const plot = page.locator('.rl-figure svg');
  assert.match(await plot.locator('title').first().textContent(), /Deviation along the path/);
  // three series: the ball from the profile per pose, the interpolated tip and axis per block
  assert.equal(await plot.locator('polyline').count(), 3);
  assert.match(await page.locator('.rl-readout').innerText(), /poses the G-code post inserted/);
  let g = await downloaded(page, /G-code/);
  assert.equal(g.name, 'toolpath.ngc');
  assert.match(g.text, /^\(ruledlab tool path: /);
  assert.match(g.text, /\(machine table-table-ac: /);
  await setControl(page, 'machine', 'head-head-ac');
  await setControl(page, 'dialect', 'heidenhain');
  await setControl(page, 'mode', 'tcp');
  g = await downloaded(page, /G-code/);
  assert.equal(g.name, 'toolpath.h');
  assert.match(g.text, /^0 BEGIN PGM RULEDLAB MM\n/);
  assert.match(g.text, /FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS/);
  assert.match(g.text, /; machine head-head-ac: C on the head about Z/);
  assert.match(page.url(), /machine=head-head-ac/);
  await setControl(page, 'dialect', 'sinumerik');
  g = await downloaded(page, /G-code/);
  assert.equal(g.name, 'TOOLPATH.MPF');
  assert.match(g.text, /^%_N_RULEDLAB_MPF\n/);
  assert.match(g.text, /TRAORI/);
  // the German page says it in German
  await showScene(page, '#scene=milling&lang=de', 'milling');
  // the scene stays (showScene finds it ready at once): wait for the texts, which come with the
  // German catalogue, loaded on demand (a fresh clone's CI once looked before it arrived)
  await page.waitForFunction(
    () =>
      /Abweichung entlang der Bahn/.test(document.querySelector('.rl-figure svg title')?.textContent ?? '') &&
      /Steuerung \(G-Code\)/.test(/** @type {HTMLElement} */ (document.querySelector('.rl-controls'))?.innerText ?? ''),
    null,
    { timeout: 20000 },
  );
  assert.deepEqual(problems, []);
  await page.close();
});

test('tool poses: ruledlab exports are recognised and round trip, a plain CSV is chosen as poses', async () => {
  const { page, problems } = await session.open('#scene=data');
  const path = ToolPath.example(5);
  try {
    // ruledlab's own CSV: recognised, opened in the milling scene with its tool
    await paste(page, path.export('csv'));
    await page.waitForFunction(
      () => /scene=milling/.test(location.hash) && /data=p0\.25~1\.5~b:/.test(decodeURIComponent(location.hash)),
    );
    await ready(page);
    assert.match(await page.locator('.rl-caption').innerText(), /Your 5 tool poses refined by 1 step/);
    assert.match(await page.locator('.rl-readout').innerText(), /poses\s+9/);
    // the poses downloaded again are the imported ones, refined: the given ones among them
    await setControl(page, 'steps', 0);
    const json = JSON.parse((await downloaded(page, /JSON/)).text);
    assert.deepEqual(json, JSON.parse(path.export('json')));
    // the JSON export, chosen explicitly; the link keeps the poses over a reload
    await paste(page, path.export('json'), 'poses');
    await page.reload();
    await ready(page);
    assert.match(await page.locator('.rl-caption').innerText(), /Your 5 tool poses/);
    await setControl(page, 'steps', 0);
    assert.equal((await downloaded(page, /CSV/)).text, path.export('csv'));
    // a plain CSV of tip and axis (no header): segments unless chosen as tool poses
    const plain = '0,0,0,0,0,1\n1,0,0.1,0.1,0,1\n2,0,0.3,0.2,0,1\n3,0,0.2,0.1,0.1,1\n';
    await paste(page, plain, 'poses');
    await page.waitForFunction(() => /data=p:/.test(decodeURIComponent(location.hash)));
    await ready(page);
    assert.match(await page.locator('.rl-caption').innerText(), /Your 4 tool poses/);
    await paste(page, plain);
    await page.waitForFunction(() => /scene=data/.test(location.hash));
    // an error is said at the paste box and the poses stay
    await showScene(page, '#scene=milling', 'milling');
    await paste(page, 'tip_x,tip_y,tip_z,axis_i,axis_j,axis_k\n0,0,0,0,0,1\n1,0,0,0,0,0\n');
    assert.match(
      await page.locator('#import-error').innerText(),
      /^CSV: pose 1 has a zero axis .*\(line 3\)\. The example data stays on screen/,
    );
    assert.deepEqual(problems, []);
  } finally {
    await page.close();
  }
});
