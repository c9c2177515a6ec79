// One operation of the benchmarks through the wasm package, repeated, for counting instructions
// with valgrind (scripts/count.sh): `node bench/count.mjs <operation> <rulings> <repeats>`.
// Operations: invariantsInPlace, invariantsInto, four-point, chaikin, bspline3, and the careful
// plain JS of bench/plainjs.mjs: js-invariants, js-four-point.
import { readFileSync } from 'node:fs';
import * as ruledlab from '../pkg/ruledlab.js';
import * as plain from './plainjs.mjs';

ruledlab.initSync({ module: readFileSync(new URL('../pkg/ruledlab_bg.wasm', import.meta.url)) });
const [op = '', rulings = '', repeats = ''] = process.argv.slice(2);
const n = Number(rulings);
const s = ruledlab.AnalyticSurface.byName('hyperboloid').sample(n, { uMin: 0, uMax: 100, closed: false });
const flat = s.segments();
const buffer = new ruledlab.InvariantsBuffer();
const reuse = s.invariants();
const out = plain.invariantsArrays(n);
const four = new Float64Array(6 * (2 * n - 1));
/** @type {Record<string, () => unknown>} */
const ops = {
  invariantsInPlace: () => s.invariantsInPlace(buffer),
  invariantsInto: () => s.invariantsInto(reuse),
  'four-point': () => s.subdivide({ scheme: 'four-point' }).free(),
  chaikin: () => s.subdivide({ scheme: 'chaikin' }).free(),
  bspline3: () => s.subdivide({ scheme: 'bspline', degree: 3 }).free(),
  'js-invariants': () => plain.invariantsInto(flat, out),
  'js-four-point': () => plain.fourPoint(flat, four),
};
const f = ops[op];
if (!f) throw new Error(`unknown operation ${op}; one of ${Object.keys(ops).join(', ')}`);
// warm up: the JIT compiles the hot loops (and V8 tiers the wasm up) before the counted calls
for (let i = 0; i < 3; i++) f();
for (let i = 0; i < Number(repeats); i++) f();
