// Times a long job of the milling scene through the built wasm package in Node (after `npm run
// build`): tool poses refined by three variational steps and posted as G-code — the routine the
// page runs in its worker (www/post-job.js) —, for 10⁴, 10⁵ and 10⁶ refined poses, with the
// share of the refinement and of the post, and the program's size. The page keeps answering
// meanwhile (tests/page/toolpath.test.mjs checks that, not the time: speed lives here).
//
// `node bench/toolpath.mjs [largest]` prints the table and writes bench/results/toolpath.json.
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { performance } from 'node:perf_hooks';
import * as ruledlab from '../pkg/ruledlab.js';
import { postSteps } from '../www/post-job.js';

ruledlab.initSync({ module: readFileSync(new URL('../pkg/ruledlab_bg.wasm', import.meta.url)) });

/** The paper's example sampled at `n` given poses (millimetres, 10 a unit), 6 numbers each. */
function givenPoses(/** @type {number} */ n) {
  const path = ruledlab.ToolPath.example(n);
  try {
    const [tips, axes] = [path.tips(), path.axes()];
    const out = new Float64Array(6 * n);
    for (let i = 0; i < n; i++) {
      for (let k = 0; k < 3; k++) {
        out[6 * i + k] = 10 * tips[3 * i + k];
        out[6 * i + 3 + k] = axes[3 * i + k];
      }
    }
    return out;
  } finally {
    path.free();
  }
}

const largest = Number(process.argv[2] ?? 1_000_000);
const rows = [];
for (const refined of [10_000, 100_000, 1_000_000].filter((n) => n <= largest)) {
  const given = Math.ceil((refined - 1) / 8) + 1;
  // the example's generator takes at most 1000 poses: longer jobs mill its profile to and fro,
  // each pass 1 mm further along Y (a raster of passes)
  const poses = given <= 1000 ? givenPoses(given) : raster(givenPoses(1000), given);
  let refineDone = 0;
  const t0 = performance.now();
  const done = await postSteps(
    {
      poses,
      tool: { radius: 2.5, length: 15, end: 'ball' },
      refine: { scheme: 'variational', variant: 'coupled', steps: 3 },
      post: { machine: 'table-table-ac', feed: 1200, scale: 1, tolerance: 0.01 },
      draw: 100_000,
    },
    (f) => {
      if (f >= 0.3 && !refineDone) refineDone = performance.now();
    },
  );
  const t1 = performance.now();
  const row = {
    poses: done.poses,
    seconds: (t1 - t0) / 1000,
    refine: (refineDone - t0) / 1000,
    post: (t1 - refineDone) / 1000,
    megabytes: done.text.length / 1e6,
    inserted: done.post.inserted,
  };
  rows.push(row);
  console.log(
    `${String(row.poses).padStart(9)} poses: ${row.seconds.toFixed(1)} s (refine ${row.refine.toFixed(1)} s, post ${row.post.toFixed(1)} s), program ${row.megabytes.toFixed(1)} MB, ${row.inserted} inserted`,
  );
}
mkdirSync(new URL('./results/', import.meta.url), { recursive: true });
writeFileSync(new URL('./results/toolpath.json', import.meta.url), `${JSON.stringify(rows, null, 2)}\n`);

/** `count` poses: the 1000 given milled to and fro, each pass 1 mm further along Y. */
function raster(/** @type {Float64Array} */ base, /** @type {number} */ count) {
  const out = new Float64Array(6 * count);
  const n = base.length / 6;
  for (let i = 0; i < count; i++) {
    const pass = Math.floor(i / n);
    const k = pass % 2 === 0 ? i % n : n - 1 - (i % n);
    out.set(base.subarray(6 * k, 6 * k + 6), 6 * i);
    out[6 * i + 1] += pass;
  }
  return out;
}
