// The "Focal surfaces" scene (beyond the paper): the kinds, the focal sheets and the torsal
// strokes are drawn from the core's buffers and respond to their controls; the readouts state
// what the tests of the core prove (an elliptic congruence has no real focal point; the normals
// of an ellipsoid have normality near 0; Example 5's lines all meet the z-axis: a complex of pitch 0).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { pageSession, setControl, shoot } from './browser.mjs';
import { countChanged } from './png.mjs';

const session = pageSession();

test('focal surfaces: kinds, sheets and strokes drawn, readouts as the core computes them', async () => {
  const { page, problems } = await session.open('#scene=focal');
  const readout = () => page.locator('.rl-readout').innerText();
  assert.match(await readout(), /hyperbolic lines\s+196 \/ 196/);
  // the ellipsoid's normals: normality a few 10⁻³ on this grid (0 in the limit, second order)
  assert.match(await readout(), /normality \|cos\|\s+\d\.\d+·10⁻[³⁴⁵⁶]/);
  const base = await shoot(page, 'focal-ellipsoid');
  await setControl(page, 'sheets', false);
  const noSheets = await shoot(page, 'focal-no-sheets');
  assert.ok(countChanged(base, noSheets) > 0.02 * base.width * base.height, 'the focal sheets are drawn');
  await setControl(page, 'torsal', false);
  const noStrokes = await shoot(page, 'focal-no-strokes');
  assert.ok(countChanged(noSheets, noStrokes) > 0.002 * base.width * base.height, 'the torsal strokes are drawn');
  await setControl(page, 'congruence', 'elliptic');
  assert.match(
    await readout(),
    /hyperbolic lines\s+0 \/ 196[\s\S]*elliptic lines\s+196 \/ 196[\s\S]*normality \|cos\|\s+none real[\s\S]*a linear congruence/,
  );
  await setControl(page, 'congruence', 'example5');
  assert.match(await readout(), /one linear complex[\s\S]*pitch of the complex\s+exact/);
  assert.match(await page.locator('.rl-sr-only[id$=description]').first().textContent(), /Example 5/);
  assert.deepEqual(problems, []);
  await page.close();
});

test('the linear complex in the striction scene: a helical surface has one, with its axis drawn on request; the hyperboloid is a regulus', async () => {
  const { page, problems } = await session.open('#scene=striction&surface=helical');
  assert.match(await page.locator('.rl-readout').innerText(), /linear complex\s+one linear complex/);
  const before = await shoot(page, 'striction-no-axis');
  await setControl(page, 'axis', true);
  const after = await shoot(page, 'striction-axis');
  assert.ok(countChanged(before, after) > 200, 'the axis is drawn');
  await setControl(page, 'surface', 'hyperboloid');
  assert.match(await page.locator('.rl-readout').innerText(), /linear complex\s+a regulus/);
  assert.deepEqual(problems, []);
  await page.close();
});

test('your data: an imported grid of lines gets its focal geometry in the data scene', async () => {
  const { page, problems } = await session.open('#scene=data');
  await page.locator('.io summary').click();
  // lines from (u, 0, −1) to (0, v, 1) on a 4 × 5 grid: focal points exactly the two ends
  const segments = [];
  for (let i = 0; i < 4; i++) for (let j = 0; j < 5; j++) segments.push([i - 1.5, 0, -1, 0, j * 0.5 - 1, 1]);
  await page.locator('#import-text').fill(JSON.stringify({ rows: 4, cols: 5, segments }));
  await page.locator('#import-button').click();
  await page.waitForFunction(() => /4 × 5/.test(document.querySelector('.rl-readout')?.textContent ?? ''));
  await setControl(page, 'focal', true);
  assert.match(await page.locator('.rl-readout').innerText(), /hyperbolic lines\s+20 \/ 20[\s\S]*a linear congruence/);
  assert.deepEqual(problems, []);
  await page.close();
});
