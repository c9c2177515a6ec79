// Times the library through the built wasm package in Node (after `npm run build`), each large
// operation beside its memory limit measured in the same process, and against a plain-JS
// implementation written as carefully as the Rust (bench/plainjs.mjs, results checked to agree).
//
// The limit of an operation: the time to write its output bytes into memory that is already
// mapped plus read its input once (a copy of the input into the output, then a fill of the
// rest: memcpy and memset speed), and for reference the same into fresh memory, which on a VM
// costs page faults. An operation at 1× its limit could not be faster without writing less.
//
// `node bench/wasm.mjs` prints the tables, writes bench/results/wasm.json, and rewrites the
// book's table between <!-- bench:begin --> and <!-- bench:end --> (docs/src/internals/benchmarks.md).
import { spawnSync } from 'node:child_process';
import { existsSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { cpus, totalmem } from 'node:os';
import { performance } from 'node:perf_hooks';
import * as ruledlab from '../pkg/ruledlab.js';
import * as plain from './plainjs.mjs';
import { rewriteBlock } from '../scripts/doc-block.mjs';

ruledlab.initSync({ module: readFileSync(new URL('../pkg/ruledlab_bg.wasm', import.meta.url)) });
const { AnalyticSurface, AnalyticCongruence, InvariantsBuffer } = ruledlab;

/** Median time of `runs` calls of f (ms), after one warm-up call. */
function median(/** @type {() => unknown} */ f, runs = 7) {
  f();
  const times = [];
  for (let i = 0; i < runs; i++) {
    const t0 = performance.now();
    f();
    times.push(performance.now() - t0);
  }
  times.sort((a, b) => a - b);
  return times[Math.floor(runs / 2)];
}

/** Bytes of the invariants of n rulings (open): 19 doubles and 1 byte per pair, about. */
const invariantBytes = (/** @type {number} */ n) =>
  8 * (3 * (n - 1) + 6 * (n - 1) + 3 * (n - 1) + 3 * (n - 2) + (n - 2) + 3 * (n - 1)) + (n - 1);

/**
 * The memory limit of an operation reading `inBytes` and writing `outBytes`: into mapped
 * memory, and into fresh memory (ms, median).
 */
function limit(/** @type {number} */ inBytes, /** @type {number} */ outBytes, runs = 7) {
  const input = new Float64Array(Math.floor(inBytes / 8)).fill(1.25);
  const mapped = new Float64Array(Math.ceil(Math.max(inBytes, outBytes) / 8)).fill(0);
  const rest = Math.max(0, Math.ceil((outBytes - inBytes) / 8));
  const write = (/** @type {Float64Array} */ out) => {
    out.set(input);
    out.fill(0.5, input.length, input.length + rest);
  };
  return {
    mapped: median(() => write(mapped), runs),
    fresh: median(() => write(new Float64Array(mapped.length)), runs),
  };
}

const N = 1e6;
const hyp = AnalyticSurface.byName('hyperboloid');
const surface = hyp.sample(N, { uMin: 0, uMax: 100, closed: false });
const flat = surface.segments();
const inBytes = flat.byteLength;

// ---- the same numbers, checked
const check = (
  /** @type {string} */ what,
  /** @type {ArrayLike<number>} */ a,
  /** @type {ArrayLike<number>} */ b,
  tol = 1e-9,
) => {
  if (a.length !== b.length) throw new Error(`${what}: lengths ${a.length} and ${b.length}`);
  for (let i = 0; i < a.length; i++) {
    const x = a[i],
      y = b[i];
    if (!(Math.abs(x - y) <= tol * Math.max(1, Math.abs(y))) && !(Number.isNaN(x) && Number.isNaN(y)))
      throw new Error(`${what}[${i}]: ${x} vs ${y}`);
  }
};
{
  const w = surface.invariants();
  const j = plain.invariants(flat);
  for (const k of Object.keys(j)) check(`invariants.${k}`, /** @type {any} */ (j)[k], /** @type {any} */ (w)[k]);
  const four = surface.subdivide({ scheme: 'four-point' });
  check('four-point', plain.fourPoint(flat), four.segments(), 0);
  four.free();
}

// criterion's median of the same operation natively (when `cargo bench` ran before: npm run bench)
const nativeMs = (/** @type {string} */ group, /** @type {number} */ id) => {
  try {
    const e = JSON.parse(
      readFileSync(new URL(`../target/criterion/${group}/${id}/new/estimates.json`, import.meta.url), 'utf8'),
    );
    return e.median.point_estimate / 1e6;
  } catch {
    return NaN;
  }
};

// The same operation natively, measured in the same minute as the wasm one (this machine's speed
// swings between minutes): examples/count.rs (release), the median of `repeats` calls, with
// glibc keeping freed memory for reuse as wasm does (scripts/bench.sh). Without that build,
// criterion's median from `cargo bench`.
const countBinary = new URL('../target/release/examples/count', import.meta.url).pathname;
const beside = (
  /** @type {string} */ op,
  /** @type {number} */ n,
  /** @type {number} */ repeats,
  /** @type {string} */ group,
) => {
  if (!existsSync(countBinary)) return nativeMs(group, n);
  const r = spawnSync(countBinary, [op, `${n}`, `${repeats}`], {
    encoding: 'utf8',
    env: { ...process.env, GLIBC_TUNABLES: 'glibc.malloc.mmap_max=0:glibc.malloc.trim_threshold=4294967295' },
  });
  const m = /: ([\d.]+) ms/.exec(r.stderr);
  return m ? Number(m[1]) : NaN;
};

// ---- operations at 10⁶ rulings, each beside its limit
const rows = [];
/** @param {string} op @param {number} ms @param {number} outBytes @param {'mapped' | 'fresh'} kind @param {number | null} js @param {number} native */
const row = (op, ms, outBytes, kind, js = null, native = NaN) => {
  const l = limit(inBytes, outBytes);
  rows.push({
    op,
    ms,
    limitMs: l[kind],
    freshLimitMs: l.fresh,
    kind,
    ofLimit: ms / l[kind],
    jsMs: js,
    versusJs: js === null ? null : js / ms,
    outMB: outBytes / 1e6,
    nativeMs: native,
    nativeOfLimit: native / l[kind],
    nativeOfWasm: native / ms,
  });
};

const outInv = invariantBytes(N);
const reuse = surface.invariants();
const buffer = new InvariantsBuffer();
const jsOut = plain.invariantsArrays(N);
// (no native number for fresh arrays: natively the result's memory is reused, see scripts/bench.sh)
row(
  'invariants() — fresh arrays',
  median(() => surface.invariants(), 5),
  outInv,
  'fresh',
  median(() => plain.invariants(flat), 5),
);
row(
  'invariantsInto(reused arrays)',
  median(() => surface.invariantsInto(reuse), 5),
  outInv,
  'mapped',
  median(() => plain.invariantsInto(flat, jsOut), 5),
  beside('invariants', N, 11, 'invariants_into'),
);
row(
  'invariantsInPlace(buffer) — zero-copy views',
  median(() => {
    surface.invariantsInPlace(buffer);
    return buffer.striction.length;
  }, 5),
  outInv,
  'mapped',
  median(() => plain.invariantsInto(flat, jsOut), 5),
  beside('invariants', N, 11, 'invariants_into'),
);

const jsFourOut = new Float64Array(6 * (2 * N - 1));
for (const [name, options, js, op, group] of /** @type {const} */ ([
  [
    'four-point step',
    { scheme: 'four-point' },
    () => plain.fourPoint(flat, jsFourOut),
    'four-point',
    'subdivide_four-point',
  ],
  ['Chaikin step', { scheme: 'chaikin' }, null, 'chaikin', 'subdivide_chaikin'],
  ['cubic B-spline step', { scheme: 'bspline', degree: 3 }, null, 'bspline3', 'subdivide_bspline3'],
])) {
  const probe = surface.subdivide(options);
  const outBytes = 48 * probe.length;
  probe.free();
  row(
    name,
    median(() => surface.subdivide(options).free(), 5),
    outBytes,
    'mapped',
    js ? median(js, 5) : null,
    beside(op, N, 11, group),
  );
}

// ---- small calls: 10³ rulings, against native
const small = [];
for (const n of [1e3, 1e4]) {
  const s = hyp.sample(n, { uMin: 0, uMax: 100, closed: false });
  const f = s.segments();
  const r = s.invariants();
  const b = new InvariantsBuffer();
  const j = plain.invariantsArrays(n);
  const four = new Float64Array(6 * (2 * n - 1));
  small.push({
    rulings: n,
    'invariants()': median(() => s.invariants(), 201),
    invariantsInto: median(() => s.invariantsInto(r), 201),
    invariantsInPlace: median(() => s.invariantsInPlace(b), 201),
    'native (fresh)': beside('invariants-fresh', n, n < 1e4 ? 2001 : 201, 'invariants'),
    'native (into)': beside('invariants', n, n < 1e4 ? 2001 : 201, 'invariants_into'),
    'plain JS (into)': median(() => plain.invariantsInto(f, j), 201),
    'four-point': median(() => s.subdivide({ scheme: 'four-point' }).free(), 201),
    'four-point plain JS': median(() => plain.fourPoint(f, four), 201),
  });
  b.free();
  s.free();
}

// ---- congruences
const congruence = [];
for (const [scheme, n, options, group, name] of /** @type {const} */ ([
  ['butterfly', 1000, { scheme: 'butterfly' }, 'butterfly', 'example5'],
  ['coupled variational', 257, { scheme: 'variational' }, 'coupled', 'example5'],
  // Example 5's x and y are affine in (u, v): the start gets them right and only z is solved;
  // on the sphere every coordinate is curved
  ['coupled variational', 257, { scheme: 'variational' }, 'coupled', 'sphere'],
])) {
  const ex = AnalyticCongruence.byName(name);
  const grid = ex.grid(n, n);
  const probe = grid.subdivide(options);
  const [inB, outB] = [48 * n * n, 48 * probe.rows * probe.cols];
  probe.free();
  const ms = median(() => grid.subdivide(options).free(), 5);
  const lim = limit(inB, outB).mapped;
  ex.free();
  const native = name === 'example5' ? nativeMs(group, n) : NaN;
  congruence.push({
    scheme,
    congruence: name === 'example5' ? 'lines of Example 5' : 'lines on a sphere (Fig. 13 left)',
    grid: `${n}²`,
    ms,
    limitMs: lim,
    ofLimit: ms / lim,
    outMB: outB / 1e6,
    nativeMs: native,
    nativeOfLimit: native / lim,
  });
  grid.free();
}

const machine = `${cpus()[0].model.trim()}, ${cpus().length} cores, ${Math.round(totalmem() / 2 ** 30)} GiB, Node ${process.version}`;
const date = new Date().toISOString().slice(0, 10);
const f = (/** @type {number | null} */ x, digits = 1) => (x === null || !Number.isFinite(x) ? '—' : x.toFixed(digits));
console.log(`wasm at 10⁶ rulings (${machine}), ms, median`);
console.table(
  rows.map((r) => ({
    op: r.op,
    ms: f(r.ms),
    'limit ms': `${f(r.limitMs)} (${r.kind})`,
    '× limit': f(r.ofLimit, 2),
    'plain JS ms': f(r.jsMs),
    'JS / wasm': f(r.versusJs, 2),
    'native / wasm': f(r.nativeOfWasm, 2),
  })),
);
console.log('small calls, ms, median');
console.table(
  small.map((r) => Object.fromEntries(Object.entries(r).map(([k, v]) => [k, k === 'rulings' ? v : f(v, 4)]))),
);
console.log('congruences, ms, median');
console.table(
  congruence.map((r) => ({
    scheme: r.scheme,
    grid: r.grid,
    ms: f(r.ms),
    'limit ms': f(r.limitMs),
    '× limit': f(r.ofLimit, 1),
  })),
);

mkdirSync(new URL('./results/', import.meta.url), { recursive: true });
writeFileSync(
  new URL('./results/wasm.json', import.meta.url),
  JSON.stringify({ date, machine, rows, small, congruence }, null, 2),
);

// ---- the book's table
const table = [
  `<!-- written by bench/wasm.mjs (npm run bench) on ${date}: ${machine} -->`,
  '',
  `Measured ${date} on ${machine}; one process, median of 5–7 runs. "Limit" is the time to write the`,
  "operation's output into already-mapped memory plus read its input once (into fresh memory for",
  '`invariants()`, which must allocate its result arrays). "Native" is the same operation in native',
  'code on the same machine, measured right after the wasm one (`examples/count.rs`, release build,',
  'median of 11 calls at 10⁶ rulings, freed memory kept for reuse as wasm keeps it; for the',
  "congruences criterion's median from `cargo bench`, run just before).",
  '',
  '| 10⁶ rulings | wasm ms | output MB | limit ms | × limit | native ms | native × limit | native / wasm | careful plain JS ms | JS / wasm |',
  '|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|',
  ...rows.map(
    (r) =>
      `| ${r.op} | ${f(r.ms)} | ${f(r.outMB, 0)} | ${f(r.limitMs)} (${r.kind}) | ${f(r.ofLimit, 2)} | ${f(r.nativeMs)} | ${f(r.nativeOfLimit, 2)} | ${f(r.nativeOfWasm, 2)} | ${f(r.jsMs)} | ${f(r.versusJs, 2)} |`,
  ),
  '',
  '| small calls, ms | `invariants()` | `invariantsInto` | `invariantsInPlace` | native (fresh) | native (into) | plain JS (into) | JS / `invariantsInPlace` | JS / `invariantsInto` | four-point step | plain JS | JS / wasm |',
  '|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|',
  ...small.map(
    (r) =>
      `| ${r.rulings} rulings | ${f(r['invariants()'], 3)} | ${f(r.invariantsInto, 3)} | ${f(r.invariantsInPlace, 3)} | ${f(r['native (fresh)'], 3)} | ${f(r['native (into)'], 3)} | ${f(r['plain JS (into)'], 3)} | ${f(r['plain JS (into)'] / r.invariantsInPlace, 2)} | ${f(r['plain JS (into)'] / r.invariantsInto, 2)} | ${f(r['four-point'], 3)} | ${f(r['four-point plain JS'], 3)} | ${f(r['four-point plain JS'] / r['four-point'], 2)} |`,
  ),
  '',
  '| congruences | wasm ms | output MB | limit ms (mapped) | × limit | native ms | native × limit |',
  '|---|---:|---:|---:|---:|---:|---:|',
  ...congruence.map(
    (r) =>
      `| ${r.scheme}, one step on ${r.grid} ${r.congruence} | ${f(r.ms)} | ${f(r.outMB, 0)} | ${f(r.limitMs)} | ${f(r.ofLimit, 1)} | ${f(r.nativeMs)} | ${f(r.nativeOfLimit, 1)} |`,
  ),
].join('\n');
if (rewriteBlock('bench', table)) console.log('docs/src/internals/benchmarks.md: benchmark table rewritten');
