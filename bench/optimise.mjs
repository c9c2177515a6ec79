// Times the pose optimisation in wasm through the built package in Node (after `npm run build`):
// the book's suite of flank cuts (docs/src/cam/tool-paths.md; the native run is
// `cargo run --release -p ruledlab-cam --example optimise`, the cases are
// crates/ruledlab-cam/tests/suite/mod.rs, rebuilt here through the JavaScript API) — the
// ruling-aligned poses (`ToolPath.rulingAligned`), `optimisePoses` as the page's worker runs it,
// and both programs posted with the target (LinuxCNC, machine coordinates, table–table A/C,
// tolerance 1 µm): the posted deviations in µm and the optimisation's time.
//
// `node bench/optimise.mjs` prints the table.
import { readFileSync } from 'node:fs';
import { performance } from 'node:perf_hooks';
import { setCamSource, startCam } from '../www/cam.js';

setCamSource(readFileSync(new URL('../pkg/cam/ruledlab_cam_bg.wasm', import.meta.url)));
const cam = await startCam();
const { ToolPath, optimisePoses } = cam;

/**
 * A case of a ruled surface p(u, v) (v ∈ [0, 1] along the ruling): `poses` rulings evenly in
 * `range`, targets at `along` × `up` points a tenth to nine tenths up, between the rulings.
 * @param {(u: number, v: number) => number[]} p @param {[number, number]} range
 * @param {number} poses @param {number} along @param {number} up
 */
function analytic(p, range, poses, along, up) {
  const rulings = [];
  for (let k = 0; k < poses; k++) {
    const u = range[0] + ((range[1] - range[0]) * k) / (poses - 1);
    rulings.push(...p(u, 0), ...p(u, 1));
  }
  const targets = [];
  for (let i = 0; i < along; i++) {
    const u = range[0] + ((range[1] - range[0]) * (i + 0.5)) / along;
    for (let j = 0; j < up; j++) targets.push(...p(u, 0.1 + (0.8 * j) / (up - 1)));
  }
  return { rulings, targets };
}

const example6 = (() => {
  const path = ToolPath.example(7).refine({ scheme: 'variational', variant: 'coupled', steps: 5 });
  const s = path.segments().map((x) => 10 * x);
  path.free();
  const n = s.length / 6;
  /** @param {number} u @param {number} v */
  const p = (u, v) => {
    const k = Math.min(Math.floor(u), n - 2);
    const t = u - k;
    const at = (/** @type {number} */ o) => (1 - t) * s[6 * k + o] + t * s[6 * (k + 1) + o];
    return [0, 1, 2].map((c) => (1 - v) * at(c) + v * at(3 + c));
  };
  return { p, last: n - 1 };
})();
const rad = Math.PI / 180;
const CASES = [
  {
    name: 'hyperbolic paraboloid',
    ...analytic((u, v) => [u, (u * 30 * v) / 60, 30 * v], [-30, 30], 41, 200, 5),
    tool: { radius: 5, length: 40, end: /** @type {const} */ ('flat') },
    side: 1,
  },
  {
    name: 'Example 6 (axis surface)',
    ...analytic(example6.p, [0, example6.last], 49, 240, 5),
    tool: { radius: 2.5, length: 25, end: /** @type {const} */ ('ball') },
    side: 1,
  },
  {
    name: 'twisted blade',
    ...analytic(
      (u, v) => {
        const b = (-20 + (40 * u) / 70) * rad;
        const d = [0.2 * Math.sin(u / 20), Math.sin(b), Math.cos(b)];
        const l = Math.hypot(...d);
        return [u + (30 * v * d[0]) / l, 4 * Math.sin(u / 25) + (30 * v * d[1]) / l, (30 * v * d[2]) / l];
      },
      [0, 70],
      57,
      280,
      5,
    ),
    tool: { radius: 3, length: 40, end: /** @type {const} */ ('ball') },
    side: 1,
  },
  {
    name: 'closed ring (hyperboloid)',
    ...analytic(
      (u, v) => {
        const [s, c, b, h] = [Math.sin(u * rad), Math.cos(u * rad), 30 * rad, 20 / Math.cos(30 * rad)];
        return [40 * c - h * v * Math.sin(b) * s, 40 * s + h * v * Math.sin(b) * c, h * v * Math.cos(b)];
      },
      [0, 360],
      121,
      300,
      4,
    ),
    tool: { radius: 5, length: 30, end: /** @type {const} */ ('flat') },
    side: -1,
  },
];

const um = (/** @type {{gouge: number, leave: number, rms: number}} */ d) =>
  [d.gouge, d.leave, d.rms].map((x) => (1e3 * x).toFixed(1)).join(' / ');
console.log('| case | baseline gouge / leave / RMS (µm) | optimised | largest | rounds | wasm time |');
console.log('|---|---:|---:|---:|---:|---:|');
for (const c of CASES) {
  const baseline = ToolPath.rulingAligned(c.rulings, c.tool, /** @type {1 | -1} */ (c.side));
  const options = { target: c.targets, tolerance: 0.001 };
  const before = baseline.post(options).deviation;
  const t0 = performance.now();
  const r = optimisePoses(baseline, c.targets);
  const ms = performance.now() - t0;
  const optimised = ToolPath.fromPoses(r.poses, baseline.tool);
  const after = optimised.post(options).deviation;
  if (!before || !after) throw new Error('a post without its deviation');
  const less = 100 * (1 - Math.abs(after.largest) / Math.abs(before.largest));
  console.log(
    `| ${c.name} | ${um(before)} | ${um(after)} | ${less.toFixed(1)} % less | ${r.rounds} | ${(ms / 1000).toFixed(2)} s |`,
  );
  baseline.free();
  optimised.free();
}
