// Two builds of the package side by side in one process, with the careful plain JS between
// them, for judging a change on a shared machine whose speed swings from one minute to the next:
//
//   cp -r pkg /tmp/pkg-before   # before the change (then rebuild with `npm run build`)
//   node bench/compare.mjs /tmp/pkg-before [rounds]
//
// Each round times every operation once in each build and in JS, in turn, so that a slow phase
// of the machine hits all of them; the table gives the fastest and the median round (ms) and
// the ratio of the medians. Nothing is written.
import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { performance } from 'node:perf_hooks';
import { pathToFileURL } from 'node:url';
import * as plain from './plainjs.mjs';

const [dir = '', roundsArg = '9'] = process.argv.slice(2);
if (!dir) throw new Error('usage: node bench/compare.mjs <directory of the other pkg/> [rounds]');
const rounds = Number(roundsArg);

/** @param {string} pkg */
async function load(pkg) {
  const m = await import(pathToFileURL(resolve(pkg, 'ruledlab.js')).href);
  m.initSync({ module: readFileSync(resolve(pkg, 'ruledlab_bg.wasm')) });
  return m;
}
const builds = { before: await load(dir), after: await load(new URL('../pkg/', import.meta.url).pathname) };

/** @type {Map<string, (() => unknown)>} */
const ops = new Map();
for (const n of [1e6, 1e3]) {
  const tag = n === 1e6 ? '10⁶' : '10³';
  let flat = new Float64Array(0);
  for (const [name, m] of Object.entries(builds)) {
    const s = m.AnalyticSurface.byName('hyperboloid').sample(n, { uMin: 0, uMax: 100, closed: false });
    flat = s.segments();
    const reuse = s.invariants();
    const buffer = new m.InvariantsBuffer();
    ops.set(`invariantsInPlace ${tag} [${name}]`, () => s.invariantsInPlace(buffer));
    ops.set(`invariantsInto ${tag} [${name}]`, () => s.invariantsInto(reuse));
    ops.set(`four-point ${tag} [${name}]`, () => s.subdivide({ scheme: 'four-point' }).free());
    ops.set(`Chaikin ${tag} [${name}]`, () => s.subdivide({ scheme: 'chaikin' }).free());
    ops.set(`cubic B-spline ${tag} [${name}]`, () => s.subdivide({ scheme: 'bspline', degree: 3 }).free());
  }
  const out = plain.invariantsArrays(n);
  const four = new Float64Array(6 * (2 * n - 1));
  ops.set(`invariants ${tag} [plain JS]`, () => plain.invariantsInto(flat, out));
  ops.set(`four-point ${tag} [plain JS]`, () => plain.fourPoint(flat, four));
}

/** @type {Map<string, number[]>} */
const times = new Map([...ops.keys()].map((k) => [k, []]));
for (let r = 0; r <= rounds; r++) {
  for (const [k, f] of ops) {
    // small calls: the time of 200 calls, per call
    const reps = k.includes('10³') ? 200 : 1;
    const t0 = performance.now();
    for (let i = 0; i < reps; i++) f();
    const t = (performance.now() - t0) / reps;
    if (r > 0) times.get(k)?.push(t); // round 0 warms up
  }
}
const stats = (/** @type {number[]} */ t) => {
  const s = [...t].sort((a, b) => a - b);
  return { min: s[0], median: s[Math.floor(s.length / 2)] };
};
const rows = [...times].map(([k, t]) => ({ op: k, ...stats(t) }));
const median = (/** @type {string} */ k) => rows.find((r) => r.op === k)?.median ?? NaN;
console.table(
  rows.map((r) => {
    const base = r.op.replace(/ \[.*\]$/, '');
    const js = median(`${base.replace(/^(invariantsInPlace|invariantsInto)/, 'invariants')} [plain JS]`);
    return {
      op: r.op,
      'min ms': r.min.toFixed(r.min < 1 ? 4 : 1),
      'median ms': r.median.toFixed(r.median < 1 ? 4 : 1),
      'before / this': (median(`${base} [before]`) / r.median).toFixed(2),
      'JS / this': Number.isFinite(js) ? (js / r.median).toFixed(2) : '—',
    };
  }),
);
