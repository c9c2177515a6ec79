// Times Section 2's invariants through the built wasm package for 10³ … 10⁶ rulings:
// `node bench/wasm.mjs` (after `npm run build`). Prints a table (median of several runs)
// and writes bench/results/wasm.json.
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { cpus } from 'node:os';
import { performance } from 'node:perf_hooks';
import * as ruledlab from '../pkg/ruledlab.js';
import * as plain from './plainjs.mjs';

ruledlab.initSync({ module: readFileSync(new URL('../pkg/ruledlab_bg.wasm', import.meta.url)) });
const { AnalyticSurface, RuledSurface, AnalyticCongruence } = ruledlab;

function median(f, runs) {
  const times = [];
  for (let i = 0; i < runs; i++) {
    const t0 = performance.now();
    f();
    times.push(performance.now() - t0);
  }
  times.sort((a, b) => a - b);
  return times[Math.floor(runs / 2)];
}

const rows = [];
const hyp = AnalyticSurface.byName('hyperboloid');
for (const n of [1e3, 1e4, 1e5, 1e6]) {
  const runs = n >= 1e6 ? 7 : 15;
  const surface = hyp.sample(n);
  const flat = surface.segments();
  const invariants = median(() => surface.invariants(), runs);
  const reuse = surface.invariants();
  const invariantsInto = median(() => surface.invariantsInto(reuse), runs);
  const fromSegments = median(() => RuledSurface.fromSegments(flat).free(), runs);
  rows.push({ rulings: n, invariantsMs: invariants, invariantsIntoMs: invariantsInto, fromSegmentsMs: fromSegments, nsPerRuling: (invariants * 1e6) / n });
  surface.free();
}
const subdivision = [];
for (const [name, options] of [
  ['chaikin', { scheme: 'chaikin' }],
  ['bspline3', { scheme: 'bspline', degree: 3 }],
  ['four-point', { scheme: 'four-point' }],
  ['variational', { scheme: 'variational' }],
]) {
  const row = { scheme: name };
  for (const n of [1e3, 1e4, 1e5, 1e6]) {
    const surface = hyp.sample(n, { uMin: 0, uMax: 100, closed: false });
    row[n] = median(() => surface.subdivide(options).free(), n >= 1e6 ? 5 : 11);
    surface.free();
  }
  subdivision.push(row);
}
const congruence = [];
const ex = AnalyticCongruence.byName('example5');
for (const [scheme, sizes, options] of [
  ['butterfly', [100, 300, 1000], { scheme: 'butterfly' }],
  ['coupled', [33, 65, 129, 257], { scheme: 'variational' }],
]) {
  for (const n of sizes) {
    const grid = ex.grid(n, n);
    congruence.push({ scheme, grid: `${n}²`, lines: n * n, ms: median(() => grid.subdivide(options).free(), n >= 257 ? 3 : 5) });
    grid.free();
  }
}
// wasm against a straightforward plain-JS implementation (bench/plainjs.mjs), same inputs,
// results checked to agree
const versusJs = [];
for (const n of [1e3, 1e4, 1e5, 1e6]) {
  const surface = hyp.sample(n, { uMin: 0, uMax: 100, closed: false });
  const flat = surface.segments();
  const runs = n >= 1e6 ? 5 : 11;
  const js = plain.invariants(flat);
  const wasmInv = surface.invariants();
  const agree = js.distance.every((h, i) => Math.abs(h - wasmInv.distance[i]) <= 1e-9 * Math.max(1, Math.abs(h)));
  const jsFour = plain.fourPoint(flat);
  versusJs.push({
    rulings: n,
    'invariants wasm ms': median(() => surface.invariants(), runs),
    'invariants JS ms': median(() => plain.invariants(flat), runs),
    'four-point wasm ms': median(() => surface.subdivide({ scheme: 'four-point' }).free(), runs),
    'four-point JS ms': median(() => plain.fourPoint(flat), runs),
    agree: agree && jsFour.length === 6 * (2 * n - 1),
  });
  surface.free();
}

// wasm against native: criterion's medians, when `cargo bench` has run
const nativeMs = (group, id) => {
  try {
    const e = JSON.parse(readFileSync(new URL(`../target/criterion/${group}/${id}/new/estimates.json`, import.meta.url)));
    return e.median.point_estimate / 1e6;
  } catch {
    return NaN;
  }
};
const versusNative = [1e3, 1e4, 1e5, 1e6].map((n) => {
  const wasm = rows.find((r) => r.rulings === n).invariantsMs;
  const four = subdivision.find((r) => r.scheme === 'four-point')[n];
  return {
    rulings: n,
    'invariants native/wasm': nativeMs('invariants', n) / wasm,
    'four-point native/wasm': nativeMs('subdivide_four-point', n) / four,
  };
});

const fit = (rows) => {
  const xs = rows.map((r) => Math.log(r.lines)), ys = rows.map((r) => Math.log(r.ms));
  const mx = xs.reduce((a, b) => a + b) / xs.length, my = ys.reduce((a, b) => a + b) / ys.length;
  return xs.reduce((s, x, i) => s + (x - mx) * (ys[i] - my), 0) / xs.reduce((s, x) => s + (x - mx) ** 2, 0);
};
const exponent = fit(congruence.filter((r) => r.scheme === 'coupled'));
console.log(`wasm (Node ${process.version}, ${cpus()[0].model}, ${cpus().length} cores)`);
console.table(rows.map((r) => ({
  rulings: r.rulings,
  'invariants ms': r.invariantsMs.toFixed(2),
  'invariantsInto ms': r.invariantsIntoMs.toFixed(2),
  'fromSegments ms': r.fromSegmentsMs.toFixed(2),
  'ns/ruling': r.nsPerRuling.toFixed(1),
})));
console.log('one subdivision step of a strip, ms (median)');
console.table(subdivision.map((r) => Object.fromEntries(Object.entries(r).map(([k, v]) => [k, typeof v === 'number' ? v.toFixed(2) : v]))));
console.log('wasm against plain JS (bench/plainjs.mjs), ms (median)');
console.table(versusJs.map((r) => Object.fromEntries(Object.entries(r).map(([k, v]) => [k, typeof v === 'number' && !Number.isInteger(v) ? v.toFixed(2) : v]))));
console.log('speed of wasm relative to native (native time / wasm time; 1 = equal, from target/criterion)');
console.table(versusNative.map((r) => Object.fromEntries(Object.entries(r).map(([k, v]) => [k, k === 'rulings' ? v : v.toFixed(2)]))));
console.log('one congruence step, ms (median)');
console.table(congruence.map((r) => ({ ...r, ms: r.ms.toFixed(1) })));
console.log(`coupled variational: time ∝ lines^${exponent.toFixed(2)}`);
mkdirSync(new URL('./results/', import.meta.url), { recursive: true });
writeFileSync(new URL('./results/wasm.json', import.meta.url), JSON.stringify({ node: process.version, cpu: cpus()[0].model, rows, subdivision, congruence, coupledExponent: exponent, versusJs, versusNative }, null, 2));
