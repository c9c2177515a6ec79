// Instructions per ruling of each kernel, natively and in wasm, counted by valgrind's callgrind:
// the repeatable measure on a machine shared with other work, where times swing by 1.5× from one
// minute to the next. Natively it runs examples/count.rs (release build); in wasm,
// bench/count.mjs through the built package in Node with V8's optimizing compiler only
// (--no-liftoff: the code a long run ends up in) and without its background threads
// (--predictable: otherwise the count varies by ±10 % from run to run). Each count is taken twice, with 4 and with 12
// repeats of the operation on 10⁵ rulings, so start-up, sampling and compilation cancel:
// instructions per ruling = (count₁₂ − count₄) / (8 · 10⁵). (Not for `invariantsInto`: its copy
// into JavaScript's arrays is glibc's memcpy, a `rep movsb` that valgrind counts byte by byte.)
//
// `node bench/instructions.mjs` (after `npm run build` and
// `cargo build --release --example count`; `npm run bench` does both) prints the table, writes
// bench/results/instructions.json and rewrites the book's table between
// <!-- bench-instructions:begin --> and <!-- bench-instructions:end -->.
import { spawnSync } from 'node:child_process';
import { mkdirSync, writeFileSync } from 'node:fs';
import { rewriteBlock } from '../scripts/doc-block.mjs';

const root = new URL('../', import.meta.url).pathname;
const N = 100_000;
const [FEW, MANY] = [4, 12];

/** Instructions valgrind counts for a command. @param {string[]} command */
function count(command) {
  const r = spawnSync(
    'valgrind',
    ['--tool=callgrind', '--smc-check=all', '--callgrind-out-file=/dev/null', ...command],
    {
      cwd: root,
      encoding: 'utf8',
    },
  );
  const m = /refs:\s+([\d,]+)/.exec(r.stderr);
  if (r.status !== 0 || !m) throw new Error(`valgrind ${command.join(' ')} failed:\n${r.stderr}`);
  return Number(m[1].replaceAll(',', ''));
}

/** Instructions per ruling of an operation. @param {(repeats: number) => string[]} command */
const perRuling = (command) => (count(command(MANY)) - count(command(FEW))) / ((MANY - FEW) * N);

const native = (/** @type {string} */ op) => perRuling((r) => ['target/release/examples/count', op, `${N}`, `${r}`]);
const wasm = (/** @type {string} */ op) =>
  perRuling((r) => ['node', '--no-liftoff', '--predictable', 'bench/count.mjs', op, `${N}`, `${r}`]);

const rows = [
  {
    op: 'invariants into reused arrays (`invariantsInPlace`)',
    native: native('invariants'),
    wasm: wasm('invariantsInPlace'),
  },
  { op: 'invariants, the scalar path (`Invariants::compute_from`)', native: native('invariants-scalar'), wasm: NaN },
  { op: 'four-point step', native: native('four-point'), wasm: wasm('four-point') },
  { op: 'Chaikin step', native: native('chaikin'), wasm: wasm('chaikin') },
  { op: 'cubic B-spline step', native: native('bspline3'), wasm: wasm('bspline3') },
];

const f = (/** @type {number} */ x) => (Number.isFinite(x) ? x.toFixed(0) : '—');
console.log(`instructions per ruling (callgrind, ${N} rulings)`);
console.table(rows.map((r) => ({ op: r.op, native: f(r.native), wasm: f(r.wasm) })));
mkdirSync(new URL('./results/', import.meta.url), { recursive: true });
const date = new Date().toISOString().slice(0, 10);
writeFileSync(new URL('./results/instructions.json', import.meta.url), JSON.stringify({ date, rows }, null, 2));
const table = [
  `<!-- written by bench/instructions.mjs (npm run bench) on ${date} -->`,
  '',
  `Instructions per ruling, counted by valgrind (callgrind) on ${N.toLocaleString('en')} rulings, repeatable to a few`,
  'instructions (natively: x86-64 as built by default, SSE2; wasm: the x86-64 code V8 compiles it to):',
  '',
  '| operation | native | wasm |',
  '|---|---:|---:|',
  ...rows.map((r) => `| ${r.op} | ${f(r.native)} | ${f(r.wasm)} |`),
].join('\n');
if (rewriteBlock('bench-instructions', table))
  console.log('docs/src/internals/benchmarks.md: instruction table rewritten');
