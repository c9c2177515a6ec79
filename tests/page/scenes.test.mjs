// Scene by scene: wasm objects are freed (every slider of every scene moved 100 times with the
// finalizer disabled leaves no live object and no growing memory), Fig. 1's labels do not
// overlap, exact quantities read "exact", and irrelevant controls say why they are disabled.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { pageSession, ready, control, setControl, shoot } from './browser.mjs';

const session = pageSession();

test('every slider of every scene moved 100 times: live wasm objects and wasm memory stay flat (no finalizer)', async () => {
  const page = await session.browser.newPage();
  await page.addInitScript(() => delete globalThis.FinalizationRegistry);
  await page.goto(session.url);
  await ready(page);
  assert.equal(await page.evaluate(() => typeof FinalizationRegistry), 'undefined');
  const scenes = await page.evaluate(() => window.ruledlab.scenes.map((s) => s.id));
  const report = [];
  for (const id of scenes) {
    if (id === 'large') continue; // its large jobs run in a worker of their own; the small path is covered by the others
    const result = await page.evaluate(async (sceneId) => {
      const { stage, scenes, wasm } = window.ruledlab;
      const scene = scenes.find((s) => s.id === sceneId);
      await stage.open(scene, {}, {});
      const sliders = scene.params.filter((p) => p.type === 'range');
      // one pass: every enabled slider through 100 values; a leak grows with every pass
      const pass = () => {
        for (const p of sliders) {
          if (p.unless?.(stage.params)) continue;
          for (let k = 0; k < 100; k++) {
            const span = p.max - p.min;
            const value =
              p.step >= 1
                ? p.min + ((k * 7) % (Math.floor(span / p.step) + 1)) * p.step
                : p.min + (((k * 37) % 100) / 100) * span;
            stage.setParam(p.key, value, k === 99);
          }
        }
      };
      const base = wasm.live();
      pass();
      const memory10 = wasm.memory();
      pass();
      return {
        base,
        live: wasm.live(),
        memory10,
        memory: wasm.memory(),
        error: document.querySelector('.rl-error').hidden ? '' : document.querySelector('.rl-error').textContent,
      };
    }, id);
    report.push(
      `${id}: live objects ${result.base} → ${result.live}; wasm memory after one pass ${result.memory10}, after two ${result.memory}`,
    );
    assert.equal(result.error, '', `${id}: ${result.error}`);
    assert.equal(result.live, result.base, `${id}: ${result.live - result.base} wasm objects left alive`);
    assert.equal(
      result.memory,
      result.memory10,
      `${id}: wasm memory grew from ${result.memory10} to ${result.memory} bytes in a second pass`,
    );
  }
  console.log(report.map((r) => `# ${r}`).join('\n'));
  await page.close();
});

test('Fig. 1: no label overlaps another or covers the common perpendicular, at any spacing', async () => {
  const { page, problems } = await session.open('#scene=notation');
  for (const spacing of [0.15, 0.3, 0.55, 0.9]) {
    await setControl(page, 'spacing', spacing);
    const boxes = await page.evaluate(() =>
      [...document.querySelectorAll('.rl-label')]
        .filter((e) => !e.hidden)
        .map((e) => ({ text: e.textContent, ...e.getBoundingClientRect().toJSON() })),
    );
    // the perpendicular N_{i,i+1} (f_{i,i+1} to f_{i+1,i}) runs clear of every label along its middle
    const covered = await page.evaluate(() => {
      const { viewer } = window.ruledlab.stage;
      const m = viewer.frame().viewProj;
      const k = viewer.built.keepClear;
      const rect = viewer.canvas.getBoundingClientRect();
      const project = (o) => {
        const [x, y, z] = [k[o], k[o + 1], k[o + 2]];
        const w = m[3] * x + m[7] * y + m[11] * z + m[15];
        return [
          rect.left + (((m[0] * x + m[4] * y + m[8] * z + m[12]) / w + 1) / 2) * rect.width,
          rect.top + ((1 - (m[1] * x + m[5] * y + m[9] * z + m[13]) / w) / 2) * rect.height,
        ];
      };
      const [p, q] = [project(0), project(3)];
      const labels = [...document.querySelectorAll('.rl-label')]
        .filter((e) => !e.hidden)
        .map((e) => [e.textContent, e.getBoundingClientRect()]);
      const hits = [];
      for (let t = 0.25; t <= 0.75; t += 0.05) {
        const [x, y] = [p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])];
        for (const [text, r] of labels) if (x > r.left && x < r.right && y > r.top && y < r.bottom) hits.push(text);
      }
      return hits;
    });
    assert.deepEqual(covered, [], `spacing ${spacing}: labels cover the perpendicular`);
    for (let i = 0; i < boxes.length; i++) {
      for (let j = i + 1; j < boxes.length; j++) {
        const [a, b] = [boxes[i], boxes[j]];
        const overlap =
          Math.min(a.right, b.right) - Math.max(a.left, b.left) > 1 &&
          Math.min(a.bottom, b.bottom) - Math.max(a.top, b.top) > 1;
        assert.ok(!overlap, `spacing ${spacing}: "${a.text}" overlaps "${b.text}"`);
      }
    }
  }
  assert.equal(
    (await page.locator('.rl-legend li[data-style="helper"] line').getAttribute('stroke-dasharray')) !== null,
    true,
    'the line the text calls dashed is dashed',
  );
  assert.deepEqual(problems, []);
  await page.close();
});

test('convergence on Plücker’s conoid: exact quantities say "exact", not "order NaN"; the plot speaks words', async () => {
  const { page, problems } = await session.open('#scene=convergence&surface=pluecker-conoid');
  const readout = await page.locator('.rl-readout').innerText();
  assert.match(readout, /order of fi,i\+1\s+exact/);
  assert.doesNotMatch(readout, /NaN/);
  const plot = await page.locator('.rl-figure svg').textContent();
  assert.doesNotMatch(plot, /distributionMean|footpoint \(/);
  assert.deepEqual(problems, []);
  await page.close();
});

test('controls that do nothing are disabled and say why', async () => {
  const { page, problems } = await session.open('#scene=curves&scheme=chaikin');
  assert.equal(await control(page, 'w').isDisabled(), true);
  assert.match(await page.locator('.rl-row[data-key="w"] .rl-reason').innerText(), /four-point scheme only/);
  assert.equal(
    await control(page, 'w').getAttribute('aria-describedby'),
    await page.locator('.rl-row[data-key="w"] .rl-reason').getAttribute('id'),
  );
  await control(page, 'scheme').selectOption('four-point');
  await ready(page);
  assert.equal(await control(page, 'w').isDisabled(), false);
  // Fig. 8's w = 1/13 typed exactly
  const exact = page.locator('.rl-row[data-key="w"] .rl-exact');
  await exact.fill('1/13');
  await exact.dispatchEvent('change');
  await page.waitForFunction(() => Math.abs(window.ruledlab.stage.params.w - 1 / 13) < 1e-15);
  assert.match(page.url(), /w=0\.0769230769230769/);
  assert.deepEqual(problems, []);
  await page.close();
});

/**
 * Share of horizontally adjacent pixel pairs on the model (neither is background) whose grey
 * levels jump by more than 48 of 255: moiré makes many (5.9 % with facet shading of 10 000
 * rulings), smooth shading only the outline (0.7 %).
 */
function jumpiness(/** @type {{width: number, height: number, channels: number, data: Uint8Array}} */ image) {
  const { width, height, channels, data } = image;
  const grey = (/** @type {number} */ x, /** @type {number} */ y) => {
    const k = (y * width + x) * channels;
    return 0.299 * data[k] + 0.587 * data[k + 1] + 0.114 * data[k + 2];
  };
  const background = grey(2, height - 2);
  let pairs = 0,
    jumps = 0;
  for (let y = 0; y < height; y++) {
    for (let x = 0; x + 1 < width; x++) {
      const a = grey(x, y),
        b = grey(x + 1, y);
      if (Math.abs(a - background) < 4 || Math.abs(b - background) < 4) continue;
      pairs++;
      if (Math.abs(a - b) > 48) jumps++;
    }
  }
  return jumps / Math.max(pairs, 1);
}

test('large models: no moiré on the strip, and ruling lines thinned so they stay apart', async () => {
  const { page, problems } = await session.open('#scene=large&n=10000');
  const strip = await shoot(page, 'large-strip');
  const stripJumps = jumpiness(strip);
  assert.ok(
    stripJumps < 0.02,
    `strip of 10 000 rulings: ${(100 * stripJumps).toFixed(2)} % of neighbouring pixels jump`,
  );
  await page.locator('.rl-controls [name="rulings"]').check();
  await ready(page);
  const lines = Number(
    await page
      .locator('.rl-readout dd')
      .nth(2)
      .textContent()
      .then((t) => t.replace(/\D/g, '')),
  );
  assert.ok(lines > 50 && lines <= 161, `${lines} ruling lines drawn`);
  assert.match(await page.locator('.rl-readout-note').textContent(), /One ruling in \d+ is drawn as a line/);
  assert.deepEqual(problems, []);
  await page.close();
});
