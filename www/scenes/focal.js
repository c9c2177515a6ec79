// Focal surfaces (beyond the paper): a congruence's two focal sheets where they are real, the
// torsal directions as short strokes on the director surface, its lines by kind (hyperbolic,
// elliptic, parabolic), the normality and the best-fitting linear complex. Everything comes
// from the core (LineCongruence.focal, focalSheetF32, torsalStrokesF32, linearComplex).
import { AnalyticCongruence } from '../../pkg/ruledlab.js';
import { defineScene, scoped, bounds } from '../scene.js';
import { congruenceOptions } from './common.js';
import { PRESETS } from './formula-congruence.js';

/** Formula presets shown here besides the built-in congruences. */
const EXTRA = ['ellipsoid-normals', 'two-lines', 'elliptic'];

/** Line length (reach·e) per congruence: long enough to pass the focal points. */
/** @type {Record<string, number>} */
const REACH = { 'ellipsoid-normals': 2.2, 'two-lines': 1, elliptic: 1.5, example5: 1, sphere: 1.2, 'hyperbolic-paraboloid': 1.5 };

/** An elliptic linear congruence: no real focal point anywhere. */
const ELLIPTIC = { p: ['u', 'v', '0'], e: ['-0.7*v', '0.7*u', '1'], u: ['-1', '1'], v: ['-1', '1'], grid: [8, 8], abc: [1, 1, 1] };

/**
 * An analytic congruence by menu value: a built-in, or a formula preset.
 * @param {string} name
 */
function analyticOf(name) {
  if (!EXTRA.includes(name)) return AnalyticCongruence.byName(name);
  const c = name === 'elliptic' ? ELLIPTIC : PRESETS[/** @type {keyof typeof PRESETS} */ (name)];
  const [a, b, cc] = c.abc;
  return AnalyticCongruence.fromFormulas({
    p: [c.p[0], c.p[1], c.p[2]],
    e: [c.e[0], c.e[1], c.e[2]],
    u: [c.u[0], c.u[1]],
    v: [c.v[0], c.v[1]],
    rows: c.grid[0],
    cols: c.grid[1],
    parameters: { a, b, c: cc },
  });
}

/**
 * Segments of the lines whose kind is `kind`.
 * @param {Float32Array} segments   6 per line
 * @param {Uint8Array} kinds
 * @param {number} kind
 */
function linesOfKind(segments, kinds, kind) {
  const out = new Float32Array(6 * kinds.reduce((n, k) => n + (k === kind ? 1 : 0), 0));
  let at = 0;
  kinds.forEach((k, i) => {
    if (k !== kind) return;
    out.set(segments.subarray(6 * i, 6 * i + 6), at);
    at += 6;
  });
  return out;
}

/**
 * The focal figure of a grid of lines: shared with "Your congruence".
 * @param {<O extends {free(): void}>(o: O) => O} own
 * @param {import('../../pkg/ruledlab.js').LineCongruence} grid
 * @param {{sheets: boolean, torsal: boolean}} p
 * @param {import('../scene.js').Context} ctx
 * @returns {{layers: import('../scene.js').Layer[], readouts: import('../scene.js').Readout[], sentence: string, positions: Float32Array[]}}
 */
export function focalFigure(own, grid, p, { t }) {
  const focal = grid.focal();
  const n = focal.kind.length;
  const count = [0, 1, 2].map((k) => focal.kind.reduce((s, x) => s + (x === k ? 1 : 0), 0));
  const real = Array.from(focal.normality).filter(Number.isFinite);
  const segments = grid.segmentsF32();
  /** @type {import('../scene.js').Layer[]} */
  const layers = [
    { kind: 'segments', style: 'focalHyperbolic', positions: linesOfKind(segments, focal.kind, 1) },
    { kind: 'segments', style: 'focalElliptic', positions: linesOfKind(segments, focal.kind, 0) },
    { kind: 'segments', style: 'focalParabolic', positions: linesOfKind(segments, focal.kind, 2) },
  ];
  /** @type {Float32Array[]} */
  const positions = [segments];
  if (p.sheets) {
    for (const sheet of /** @type {const} */ ([1, 2])) {
      const mesh = grid.focalSheetF32(sheet);
      if (mesh.indices.length === 0) continue;
      layers.push({ kind: 'mesh', style: `focal${sheet}`, positions: mesh.positions, indices: mesh.indices, normals: mesh.normals });
      // frame only what is drawn: vertices of kept triangles
      const used = new Float32Array(3 * mesh.indices.length);
      mesh.indices.forEach((v, k) => used.set(mesh.positions.subarray(3 * v, 3 * v + 3), 3 * k));
      positions.push(used);
    }
  }
  if (p.torsal) layers.push({ kind: 'segments', style: 'torsal', positions: grid.torsalStrokesF32() });
  // looser than the default 1e-9: imported data carry the digits a file printed
  const complex = grid.linearComplex({ tolerance: 1e-6 });
  const normality = real.length ? Math.max(...real) : NaN;
  /** @type {import('../scene.js').Readout[]} */
  const readouts = [
    { label: 'focal.readout.hyperbolic', value: `${count[1]} / ${n}` },
    { label: 'focal.readout.elliptic', value: `${count[0]} / ${n}` },
    { label: 'focal.readout.parabolic', value: `${count[2]} / ${n}` },
    { label: 'focal.readout.normality', value: real.length ? normality : t('focal.none'), exactZero: true },
    { label: 'focal.readout.complex', value: t(`complex.kind.${complex.kind}`) },
  ];
  // a pitch at rounding level is 0: the lines all meet the axis (Example 5: the z-axis)
  if (complex.kind === 'complex') readouts.push({ label: 'focal.readout.pitch', value: Math.abs(complex.pitch) < 1e-12 ? 0 : complex.pitch, exactZero: true });
  const sentence = t('focal.describe', {
    hyperbolic: count[1],
    elliptic: count[0],
    parabolic: count[2],
    lines: n,
    normality: real.length ? t('focal.describe.normality', { normality }) : '',
    complex: t(`complex.kind.${complex.kind}`),
  });
  return { layers, readouts, sentence, positions };
}

export const scene = defineScene({
  id: 'focal',
  title: 'focal.title',
  text: 'focal.text',
  params: [
    {
      key: 'congruence',
      label: 'congruence.param.congruence',
      type: 'select',
      value: 'ellipsoid-normals',
      options: () => [...congruenceOptions(), ...EXTRA.map((k) => /** @type {[string, string]} */ ([k, `congruence.${k}`]))],
      sets: (v) => ({ reach: REACH[String(v)] ?? 1 }),
    },
    { key: 'reach', label: 'focal.param.reach', type: 'range', min: 0.2, max: 4, step: 0.1, value: 2.2 },
    { key: 'n', label: 'focal.param.n', type: 'range', min: 4, max: 40, step: 1, value: 14 },
    { key: 'sheets', label: 'focal.param.sheets', type: 'checkbox', value: true },
    { key: 'torsal', label: 'focal.param.torsal', type: 'checkbox', value: true },
  ],
  legend: [
    { style: 'focalHyperbolic', label: 'focal.legend.hyperbolic' },
    { style: 'focalElliptic', label: 'focal.legend.elliptic' },
    { style: 'focal1', label: 'focal.legend.focal1', when: (p) => !!p.sheets },
    { style: 'focal2', label: 'focal.legend.focal2', when: (p) => !!p.sheets },
    { style: 'torsal', label: 'focal.legend.torsal', when: (p) => !!p.torsal },
  ],
  create(p, ctx) {
    return scoped((own) => {
      const name = String(p.congruence);
      const analytic = own(analyticOf(name));
      const n = Number(p.n);
      const grid = own(analytic.grid(n, n, Number(p.reach)));
      const figure = focalFigure(own, grid, /** @type {any} */ (p), ctx);
      return {
        bounds: bounds(...figure.positions),
        camera: { yaw: -2.1, pitch: 0.55 },
        layers: figure.layers,
        readouts: figure.readouts,
        description: `${ctx.t(`congruence.${name}`)}: ${figure.sentence}`,
        data: { segments: grid.segments(), grid: { rows: grid.rows, cols: grid.cols } },
      };
    });
  },
});
