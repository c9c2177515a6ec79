// Frame times of the page while the view orbits, for models of 10³ and 10⁵ rulings (the
// "Large models" scene; above 2 000 rulings the strip is drawn from a lighter stand-in while
// the camera moves, in full once it rests) and a small figure, in headless Chromium with software WebGL
// (SwiftShader) on this machine: judge the ratio, not the absolute numbers. A GPU draws the
// same instanced layers far faster. `node bench/page.mjs` (after npm run build).
import { cpus } from 'node:os';
import { chromium } from 'playwright-core';
import { startServer } from '../scripts/serve.mjs';
import { rewriteBlock } from '../scripts/doc-block.mjs';

const CASES = [
  ['figure (striction, 36 rulings)', '#scene=striction'],
  ['10³ rulings', '#scene=large&n=1000&steps=0&rulings=1'],
  ['10⁴ rulings', '#scene=large&n=10000&steps=0&rulings=1'],
  ['10⁵ rulings (6 301 refined 4 times: 100 801)', '#scene=large&n=6301&steps=4&rulings=1'],
  ['1.28·10⁶ rulings (10 000 refined 7 times)', '#scene=large&n=10000&steps=7&rulings=1'],
];

const { server, url } = await startServer();
const results = [];
try {
  for (const [name, hash] of CASES) {
    // a browser per case, so that no case pays for the memory of the one before
    const browser = await chromium.launch({
      executablePath: '/usr/bin/chromium',
      args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
    });
    const page = await browser.newPage({ viewport: { width: 1200, height: 800 } });
    await page.goto(url + hash);
    await page.waitForFunction(
      () => /** @type {HTMLElement | null} */ (document.querySelector('.rl-stage'))?.dataset.ready === '1',
      null,
      { timeout: 120000 },
    );
    await page.locator('.rl-view canvas').focus();
    const ms = await page.evaluate(
      () =>
        new Promise((resolve) => {
          const canvas = /** @type {HTMLCanvasElement} */ (document.querySelector('.rl-view canvas'));
          const frames0 = Number(document.body.dataset.frames ?? 0);
          const t0 = performance.now();
          const tick = () => {
            if (performance.now() - t0 > 4000) {
              resolve((performance.now() - t0) / Math.max(1, Number(document.body.dataset.frames) - frames0));
              return;
            }
            canvas.dispatchEvent(new KeyboardEvent('keydown', { key: 'ArrowLeft', bubbles: true }));
            requestAnimationFrame(tick);
          };
          requestAnimationFrame(tick);
        }),
    );
    const readout = await page.locator('.rl-readout').innerText();
    results.push({
      case: name,
      'ms per frame': Number(ms).toFixed(1),
      readout: readout.replace(/\s+/g, ' ').slice(0, 80),
    });
    await browser.close();
  }
} finally {
  server.close();
}
const base = Number(results[1]['ms per frame']);
console.log('orbiting: time per drawn frame (software WebGL)');
console.table(results.map((r) => ({ ...r, 'vs 10³': (Number(r['ms per frame']) / base).toFixed(2) })));

// the book's table (docs/src/internals/page-speed.md)
const date = new Date().toISOString().slice(0, 10);
const block = [
  `<!-- written by bench/page.mjs (npm run bench) on ${date} -->`,
  '',
  `Orbiting in the page (headless Chromium, software WebGL on ${cpus().length} cores, ${date}; judge the ratios):`,
  '',
  '| model | ms per frame | vs 10³ rulings |',
  '|---|---:|---:|',
  ...results.map((r) => `| ${r.case} | ${r['ms per frame']} | ${(Number(r['ms per frame']) / base).toFixed(2)} |`),
].join('\n');
if (rewriteBlock('bench-page', block)) console.log('docs/src/internals/page-speed.md: page benchmark rewritten');
