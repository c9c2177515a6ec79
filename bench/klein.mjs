// Frame times of the Klein view beside the 3D view for 10 000 lines (your data: a hyperboloid's
// rulings, shown by the data panel as a reader shows a file), in headless Chromium with software
// WebGL (SwiftShader) on this machine: each view draws a few frames in full one after another,
// its camera turned before each and each frame waited for. The goal: the Klein view's frame time
// at most 1.2 × the 3D view's for the same lines, both views the same size (the split view's
// halves); the 3D view alone (the whole width) for comparison. Then a step of the Klein view's α
// slider, as a reader's: from its input event to the Klein view's next frame issued (the core's
// kleinView of every line again, the buffers uploaded; the GPU's drawing not waited for). Rounds alternate, the median
// counts. `node bench/klein.mjs` (after npm run build).
import { cpus } from 'node:os';
import { chromium } from 'playwright-core';
import { startServer } from '../scripts/serve.mjs';
import { rewriteBlock } from '../scripts/doc-block.mjs';

const LINES = 10_000;
const ROUNDS = 5;
const FRAMES = 4;

// the rulings of a hyperboloid of one sheet, each line written by two of its points
const csv = Array.from({ length: LINES }, (_, i) => {
  const u = (2 * Math.PI * i) / LINES;
  const a = [Math.cos(u), Math.sin(u), -1];
  const b = [Math.cos(u + 1.2), Math.sin(u + 1.2), 1];
  return [...a, ...b].map((x) => x.toPrecision(12)).join(',');
}).join('\n');

/**
 * Milliseconds per frame of one view: `FRAMES` frames drawn in full one after another, the camera
 * turned a little before each, each waited for (a pixel read back: the GPU has finished).
 * @param {import('playwright-core').Page} page
 * @param {'space' | 'klein'} which
 */
function frameTime(page, which) {
  return page.evaluate(
    ([w, frames]) => {
      const { stage } = /** @type {any} */ (window).ruledlab;
      const viewer = w === 'klein' ? stage.kleinPane.viewer : stage.viewer;
      const pixel = new Uint8Array(4);
      const t0 = performance.now();
      for (let k = 0; k < Number(frames); k++) {
        viewer.camera.yaw += 0.02;
        viewer.render({ full: true });
        viewer.gl.readPixels(0, 0, 1, 1, viewer.gl.RGBA, viewer.gl.UNSIGNED_BYTE, pixel);
      }
      return (performance.now() - t0) / Number(frames);
    },
    /** @type {const} */ ([which, FRAMES]),
  );
}

/**
 * Milliseconds from a step of the Klein view's α slider (its input event, as a reader's drag
 * fires it) to the Klein view's next frame issued.
 * @param {import('playwright-core').Page} page
 */
function stepTime(page) {
  return page.evaluate(async () => {
    const box = /** @type {HTMLElement} */ (document.querySelector('.rl-klein'));
    const input = /** @type {HTMLInputElement} */ (document.querySelector('.rl-klein-steer input'));
    const before = Number(box.dataset.frames ?? 0);
    const t0 = performance.now();
    input.value = String(Number(input.value) >= 89 ? 1 : Number(input.value) + 1);
    input.dispatchEvent(new Event('input', { bubbles: true }));
    while (Number(box.dataset.frames ?? 0) === before) await new Promise((r) => requestAnimationFrame(r));
    return performance.now() - t0;
  });
}

const median = (/** @type {number[]} */ xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];

const { server, url } = await startServer();
/** @type {Record<string, number[]>} */
const times = { alone: [], space: [], klein: [], step: [] };
try {
  const browser = await chromium.launch({
    executablePath: '/usr/bin/chromium',
    args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
  });
  const page = await browser.newPage({ viewport: { width: 1200, height: 800 } });
  await page.goto(`${url}#scene=data`);
  await page.waitForFunction(() => document.querySelector('.rl-stage')?.getAttribute('data-ready') === '1');
  await page.locator('.io summary').click();
  // (the text set at once, as a paste would: filling it key by key takes minutes)
  await page.locator('#import-text').evaluate((area, text) => {
    /** @type {HTMLTextAreaElement} */ (area).value = text;
    area.dispatchEvent(new Event('input', { bubbles: true }));
  }, csv);
  await page.locator('#import-button').click();
  await page.waitForFunction(
    (n) => /** @type {any} */ (window).ruledlab.stage.session.built?.data?.segments.length === 6 * n,
    LINES,
    { timeout: 120000 },
  );
  for (let round = 0; round < ROUNDS; round++) {
    // the 3D view alone, then beside the Klein view, then the Klein view
    if (await page.locator('.rl-klein').isVisible()) await page.locator('.rl-klein-toggle').click();
    await page.waitForTimeout(300);
    times.alone.push(await frameTime(page, 'space'));
    await page.locator('.rl-klein-toggle').click();
    await page.waitForFunction(() => Number(document.querySelector('.rl-klein')?.getAttribute('data-frames') ?? 0) > 0);
    await page.waitForTimeout(300);
    times.space.push(await frameTime(page, 'space'));
    times.klein.push(await frameTime(page, 'klein'));
    times.step.push(await stepTime(page));
  }
  const description = await page.locator('.rl-klein .rl-sr-only').textContent();
  if (!new RegExp(`the ${LINES.toLocaleString('en').replace(',', '.?')} lines`).test(description ?? ''))
    console.log(`(the Klein view says: ${description})`);
  await browser.close();
} finally {
  server.close();
}

const [alone, space, klein, step] = [times.alone, times.space, times.klein, times.step].map(median);
const ratio = klein / space;
console.table({
  '3D view alone (whole width)': alone.toFixed(1),
  '3D view beside the Klein view': space.toFixed(1),
  'Klein view beside the 3D view': klein.toFixed(1),
  'Klein / 3D, same size': ratio.toFixed(2),
  'a step of α, input to the Klein frame': step.toFixed(1),
});

// the book's paragraph (docs/src/internals/page-speed.md)
const date = new Date().toISOString().slice(0, 10);
const block = [
  `<!-- written by bench/klein.mjs (npm run bench) on ${date} -->`,
  '',
  `The Klein view of ${LINES.toLocaleString('en').replace(',', ' ')} lines (a hyperboloid's rulings shown as your data; headless Chromium, software WebGL on ${cpus().length} cores, ${date}; each view drawing ${FRAMES} frames in full in turn, its camera turned before each and each frame waited for, the median of ${ROUNDS} rounds; judge the ratio, the goal is ≤ 1.2):`,
  '',
  '| view | ms per frame |',
  '|---|---:|',
  `| the 3D view alone (the whole width) | ${alone.toFixed(1)} |`,
  `| the 3D view beside the Klein view | ${space.toFixed(1)} |`,
  `| the Klein view beside the 3D view | ${klein.toFixed(1)} |`,
  `| **Klein view / 3D view, the same size** | **${ratio.toFixed(2)}** |`,
  '',
  `A step of the Klein view's α slider (its input event, as a reader's drag fires it) takes ${step.toFixed(0)} ms until the Klein view's next frame is issued — the image of every line computed again by the core and uploaded — and the GPU then draws it as any frame above (the median of ${ROUNDS}; the frame's drawing is not waited for here).`,
].join('\n');
if (rewriteBlock('bench-klein', block)) console.log('docs/src/internals/page-speed.md: Klein benchmark rewritten');
