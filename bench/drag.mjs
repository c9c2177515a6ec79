// Dragging the geometry of a teaching model: the time of one drag step in the core (the scene
// recomputed on the moved input, in Node, median of many steps) and, in headless Chromium with
// software WebGL, the time per drawn frame while a handle is dragged against the time per frame
// while the camera orbits the same model, side by side in one run: rounds of each, alternating,
// the median over the rounds of the time per drawn frame (judge the ratio: SwiftShader draws slowly, a GPU
// fast). The goals: under 2 ms in the core, and a drag frame costing no more than an orbit frame
// (ratio ≤ 1.05; the book, "Speed of the page").
// `node bench/drag.mjs` (after npm run build); `node bench/drag.mjs striction` times only the
// models of that scene and leaves the book alone.
import { cpus } from 'node:os';
import { chromium } from 'playwright-core';
import { startServer } from '../scripts/serve.mjs';
import { rewriteBlock } from '../scripts/doc-block.mjs';
import '../tests/node/load.mjs';
import { SCENES } from '../www/scenes/index.js';
import { defaults } from '../www/scene.js';
import { translator } from '../www/i18n/index.js';
import { inputOf } from '../www/edit/input.js';

/** Rounds of orbiting and dragging, alternating, and how long each lasts (ms). */
const ROUNDS = 5;
const SPAN = 1500;

/** [name, scene, parameters, link] — the teaching models, at the most the page offers. */
const MODELS = [
  ['160 rulings (striction)', 'striction', { n: 160 }, '#scene=striction&n=160'],
  ['20 × 20 lines (focal)', 'focal', { n: 20 }, '#scene=focal&n=20'],
  [
    '8 × 7 lines, 3 steps (congruence, butterfly)',
    'congruence',
    { scheme: 'butterfly', steps: 3 },
    '#scene=congruence&scheme=butterfly&steps=3',
  ],
  ['12 tool poses, 1 step (milling)', 'milling', { poses: 12 }, '#scene=milling&poses=12'],
  ['8 control points, 6 steps (curves)', 'curves', { steps: 6 }, '#scene=curves&steps=6'],
  ['200 rulings (paper models, tangent surface)', 'developable', { n: 200 }, '#scene=developable&n=200'],
];

const i18n = translator('en');
const median = (/** @type {number[]} */ xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];

/** The core's part of one drag step: the scene computed on its input with one handle moved. */
function coreStep(/** @type {string} */ id, /** @type {Record<string, any>} */ extra) {
  const scene = /** @type {import('../www/scene.js').Scene} */ (SCENES.find((s) => s.id === id));
  const params = { ...defaults(scene), ...extra };
  const context = { t: i18n.t, format: i18n.format, lang: 'en' };
  const built = scene.create(params, context);
  const input = inputOf(/** @type {NonNullable<typeof built.input>} */ (built.input).sets);
  const key = Object.keys(input)[0];
  const times = [];
  for (let k = 0; k < 60; k++) {
    input[key][3] += 1e-3 * Math.sin(k); // the handle moves a little every step
    const t0 = performance.now();
    scene.create(params, { ...context, input });
    times.push(performance.now() - t0);
  }
  return median(times.slice(10));
}

/**
 * Frame times in the page, side by side: rounds of orbiting (a key per frame) and of dragging a
 * handle (synthetic pointer events, one per frame) on the same model, alternating, so that a
 * machine busy with other work slows both alike; of each, the median over the rounds of the time
 * per drawn frame.
 */
async function frameTimes(/** @type {string} */ url) {
  const browser = await chromium.launch({
    executablePath: '/usr/bin/chromium',
    args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
  });
  try {
    const page = await browser.newPage({ viewport: { width: 1200, height: 800 } });
    await page.goto(url);
    await page.waitForFunction(() => document.querySelector('.rl-stage')?.dataset.ready === '1', null, {
      timeout: 120000,
    });
    return await page.evaluate(
      async ({ rounds, span }) => {
        const stage = /** @type {any} */ (window).ruledlab.stage;
        const canvas = /** @type {HTMLCanvasElement} */ (stage.viewer.canvas);
        const frames = () => Number(document.body.dataset.frames ?? 0);
        /** Runs `step` once per animation frame for `span` ms; the time per drawn frame (the round's mean). */
        const measure = (/** @type {(k: number) => void} */ step) =>
          new Promise((resolve) => {
            const f0 = frames();
            const t0 = performance.now();
            let k = 0;
            const tick = (/** @type {number} */ now) => {
              if (now - t0 > span) return resolve((now - t0) / Math.max(1, frames() - f0));
              step(k++);
              requestAnimationFrame(tick);
            };
            requestAnimationFrame(tick);
          });
        /**
         * A handle near the middle of the view, chosen as from the list of points on top of each
         * other (a press then takes it whatever lies beside it).
         */
        const handle = () => {
          const r = canvas.getBoundingClientRect();
          const m = stage.viewer.camera.viewProj(r.width / r.height);
          const c = { x: r.left + r.width / 2, y: r.top + r.height / 2 };
          const screen = stage.editor.handles().map((/** @type {{world: number[]}} */ h, /** @type {number} */ k) => {
            const [x, y, z] = h.world;
            const w = m[3] * x + m[7] * y + m[11] * z + m[15];
            const s = {
              k,
              x: r.left + (((m[0] * x + m[4] * y + m[8] * z + m[12]) / w + 1) / 2) * r.width,
              y: r.top + ((1 - (m[1] * x + m[5] * y + m[9] * z + m[13]) / w) / 2) * r.height,
            };
            return { ...s, d: w > 0 ? Math.hypot(s.x - c.x, s.y - c.y) : Infinity };
          });
          const h = screen.sort((/** @type {{d: number}} */ a, /** @type {{d: number}} */ b) => a.d - b.d)[0];
          stage.editor.select(h.k, true);
          return h;
        };
        const pointer = (/** @type {string} */ type, /** @type {number} */ x, /** @type {number} */ y) =>
          canvas.dispatchEvent(
            new PointerEvent(type, {
              pointerId: 7,
              pointerType: 'mouse',
              button: 0,
              buttons: 1,
              clientX: x,
              clientY: y,
              bubbles: true,
            }),
          );
        /** @type {number[]} */
        const core = [];
        const compute = stage.compute.bind(stage);
        const timed = (/** @type {any} */ o) => {
          const t0 = performance.now();
          const built = compute(o);
          core.push(performance.now() - t0);
          return built;
        };
        /** @type {number[]} */
        const orbit = [];
        /** @type {number[]} */
        const drag = [];
        for (let round = 0; round < rounds; round++) {
          orbit.push(
            await measure(() =>
              canvas.dispatchEvent(new KeyboardEvent('keydown', { key: 'ArrowLeft', bubbles: true })),
            ),
          );
          const h = handle();
          pointer('pointerdown', h.x, h.y);
          if (!stage.editor.drag) throw new Error('the press took no handle');
          stage.compute = timed;
          drag.push(
            await measure((k) => pointer('pointermove', h.x + 30 * Math.sin(k / 10), h.y + 30 * Math.cos(k / 10))),
          );
          pointer('pointerup', h.x, h.y);
          stage.compute = compute;
        }
        const median = (/** @type {number[]} */ xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)] ?? NaN;
        return { orbit: median(orbit), drag: median(drag), page: median(core) };
      },
      { rounds: ROUNDS, span: SPAN },
    );
  } finally {
    await browser.close();
  }
}

const { server, url } = await startServer();
const rows = [];
try {
  const only = process.argv[2];
  for (const [name, id, extra, hash] of MODELS.filter(([, id]) => !only || id === only)) {
    const core = coreStep(id, extra);
    const f = await frameTimes(url + hash);
    rows.push({ name, core, page: f.page, orbit: f.orbit, drag: f.drag });
    console.log(name, {
      core: core.toFixed(2),
      page: f.page.toFixed(2),
      orbit: f.orbit.toFixed(1),
      drag: f.drag.toFixed(1),
    });
  }
} finally {
  server.close();
}

const date = new Date().toISOString().slice(0, 10);
const block = [
  `<!-- written by bench/drag.mjs (npm run bench) on ${date} -->`,
  '',
  `Dragging a handle (${cpus().length} cores, ${date}): one drag step recomputes the scene on the moved input — in Node (the core and the scene's glue, median of 50 steps) and in the page (the same, plus building the GPU buffers' data) — and the page draws it; frame times in headless Chromium with software WebGL, dragging against orbiting the same model side by side (${ROUNDS} rounds of ${SPAN / 1000} s each, alternating; the median over the rounds of the time per drawn frame; judge the ratio, the goal is ≤ 1.05).`,
  '',
  '| model | drag step, Node ms | drag step in the page, ms | ms per frame orbiting | ms per frame dragging | dragging / orbiting |',
  '|---|---:|---:|---:|---:|---:|',
  ...rows.map(
    (r) =>
      `| ${r.name} | ${r.core.toFixed(2)} | ${r.page.toFixed(2)} | ${r.orbit.toFixed(1)} | ${r.drag.toFixed(1)} | ${(r.drag / r.orbit).toFixed(2)} |`,
  ),
].join('\n');
if (!process.argv[2] && rewriteBlock('bench-drag', block))
  console.log('docs/src/internals/page-speed.md: drag benchmark rewritten');
