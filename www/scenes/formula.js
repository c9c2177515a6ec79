// Your surface: x(u, v) = a(u) + v·e(u) typed as formulas, with every tool of Sections 2–4 on
// it: the striction polygon against the exact striction curve, the convergence orders,
// bending, the approximate development, and subdivision. The core parses the formulas and
// differentiates them exactly; the formulas live in the link, so a lecturer can link an exercise.
import { AnalyticSurface } from '../../pkg/ruledlab.js';
import { defineScene, scoped, bounds } from '../scene.js';
import { stripIndices } from '../gl/mesh.js';
import { strictionFigure } from './striction.js';
import { convergenceFigure } from './convergence.js';
import { isometryFigure } from './isometry.js';

/** The built-in surfaces (and a few more) as formulas: a(u), e(u), u range, v range, closed, a, b, c. */
export const PRESETS = {
  hyperboloid: { a: ['a*cos(u)', 'b*sin(u)', '0'], e: ['-a*sin(u)', 'b*cos(u)', 'c'], u: ['0', '2*pi'], v: ['-1', '1'], closed: true, abc: [1, 2, 3] },
  quartic: { a: ['1', 'u^2/2', 'u'], e: ['u^2', 'u', '-1'], u: ['-1', '1'], v: ['-1', '1'], closed: false, abc: [1, 1, 1] },
  helicoid: { a: ['0', '0', 'a*u'], e: ['cos(u)', 'sin(u)', '0'], u: ['0', '4*pi'], v: ['-1', '1'], closed: false, abc: [0.5, 1, 1] },
  helical: { a: ['cos(u)', 'sin(u)', 'a*u'], e: ['-cos(b)*sin(u)', 'cos(b)*cos(u)', 'sin(b)'], u: ['0', '9'], v: ['-0.8', '0.8'], closed: false, abc: [0.4, 0.79, 1] },
  'helical-orthogonal': { a: ['cos(u)', 'sin(u)', 'a*u'], e: ['-cos(b)*sin(u)', 'cos(b)*cos(u)', 'sin(b)'], u: ['0', '9'], v: ['-0.8', '0.8'], closed: false, abc: [0.4, -1.19, 1] },
  'pluecker-conoid': { a: ['0', '0', 'sin(2*u)'], e: ['cos(u)', 'sin(u)', '0'], u: ['0', '2*pi'], v: ['-1', '1'], closed: true, abc: [1, 1, 1] },
  'hyperbolic-paraboloid': { a: ['u', '0', '0'], e: ['0', '1', 'u'], u: ['-1', '1'], v: ['-1', '1'], closed: false, abc: [1, 1, 1] },
  cone: { a: ['0.5', '-0.2', '1'], e: ['2*cos(u)', 'sin(u)', '1'], u: ['0', '2*pi'], v: ['0.2', '1.2'], closed: true, abc: [1, 1, 1] },
  'helix-tangent': { a: ['cos(u)', 'sin(u)', 'a*u'], e: ['-sin(u)', 'cos(u)', 'a'], u: ['0', '2*pi'], v: ['0.1', '1.2'], closed: false, abc: [0.3, 1, 1] },
  moebius: { a: ['cos(u)', 'sin(u)', '0'], e: ['cos(u/2)*cos(u)', 'cos(u/2)*sin(u)', 'sin(u/2)'], u: ['0', '2*pi'], v: ['-0.35', '0.35'], closed: false, abc: [1, 1, 1] },
};

/** The parameters a preset sets. */
/** @returns {import('../scene.js').Params} */
function presetParams(/** @type {string} */ name) {
  const p = PRESETS[/** @type {keyof typeof PRESETS} */ (name)];
  if (!p) return {};
  return {
    ax: p.a[0], ay: p.a[1], az: p.a[2], ex: p.e[0], ey: p.e[1], ez: p.e[2],
    umin: p.u[0], umax: p.u[1], vmin: p.v[0], vmax: p.v[1], closed: p.closed, a: p.abc[0], b: p.abc[1], c: p.abc[2],
  };
}

const HYPERBOLOID = presetParams('hyperboloid');
const TOOLS = ['striction', 'convergence', 'bending', 'development', 'subdivision'];
/** @param {string[]} tools @returns {(p: import('../scene.js').Params) => string | null} */
const onlyFor = (...tools) => (p) => (tools.includes(String(p.tool)) ? null : 'formula.reason.tool');

/** @type {Record<string, string>} */
const FIELDS = { 'a[0]': 'ax', 'a[1]': 'ay', 'a[2]': 'az', 'e[0]': 'ex', 'e[1]': 'ey', 'e[2]': 'ez', 'u[0]': 'umin', 'u[1]': 'umax', 'v[0]': 'vmin', 'v[1]': 'vmax', u: 'umin', v: 'vmin', e: 'ex', parameters: 'a' };

/** A text parameter holding a formula. */
const formula = (/** @type {string} */ key, /** @type {string} */ value) => ({ key, label: `formula.param.${key}`, type: /** @type {const} */ ('text'), value });

/**
 * The subdivision figure of a sampled surface: old rulings, inserted rulings, and how far the
 * inserted ones are from the exact surface.
 * @param {<O extends {free(): void}>(o: O) => O} own
 * @param {import('../../pkg/ruledlab.js').AnalyticSurface} analytic
 * @param {{uMin: number, uMax: number, closed: boolean}} ranges
 * @param {{n: number, scheme: string, steps: number}} p
 * @param {import('../scene.js').Context} ctx
 * @returns {import('../scene.js').Built}
 */
export function subdivisionFigure(own, analytic, ranges, p, { t }) {
  const surface = own(analytic.sample(p.n, { ...ranges, closed: false }));
  const steps = Number(p.steps);
  /** @type {import('../../pkg/ruledlab.js').SubdivideOptions} */
  const options = p.scheme === 'lines' ? { scheme: 'four-point', space: 'lines', steps } : { scheme: /** @type {import('../../pkg/ruledlab.js').SubdivideOptions['scheme']} */ (p.scheme), steps };
  const refined = own(surface.subdivide(options));
  const stride = 2 ** p.steps;
  const distance = analytic.insertedDistance(refined, stride, ranges.uMin, ranges.uMax);
  const seg = refined.segmentsF32();
  return {
    bounds: bounds(seg),
    camera: { yaw: -1.2, pitch: 0.45 },
    layers: [
      { kind: 'segments', style: 'given', positions: surface.segmentsF32() },
      { kind: 'segments', style: refined.length > 400 ? 'insertedFine' : 'inserted', positions: refined.insertedF32(stride) },
      { kind: 'mesh', style: 'strip', positions: seg, indices: stripIndices(refined.length) },
    ],
    readouts: [
      { label: 'readout.rulings', value: refined.length },
      { label: 'strip.readout.distance', value: distance, exactZero: true },
    ],
    description: t('formula.describeSubdivision', { n: p.n, steps: p.steps, total: refined.length, distance }),
    data: { segments: refined.segments() },
  };
}

export const scene = defineScene({
  id: 'formula',
  title: 'formula.title',
  text: 'formula.text',
  params: [
    { key: 'preset', label: 'formula.param.preset', type: 'select', value: 'hyperboloid', options: () => Object.keys(PRESETS).map((k) => [k, `surface.${k}`]), sets: (v) => presetParams(String(v)) },
    formula('ax', String(HYPERBOLOID.ax)), formula('ay', String(HYPERBOLOID.ay)), formula('az', String(HYPERBOLOID.az)),
    formula('ex', String(HYPERBOLOID.ex)), formula('ey', String(HYPERBOLOID.ey)), formula('ez', String(HYPERBOLOID.ez)),
    formula('umin', '0'), formula('umax', '2*pi'), formula('vmin', '-1'), formula('vmax', '1'),
    { key: 'closed', label: 'formula.param.closed', type: 'checkbox', value: true },
    { key: 'a', label: 'formula.param.a', type: 'range', min: -3, max: 3, step: 0.01, value: 1, exact: true, play: true },
    { key: 'b', label: 'formula.param.b', type: 'range', min: -3, max: 3, step: 0.01, value: 2, exact: true, play: true },
    { key: 'c', label: 'formula.param.c', type: 'range', min: -3, max: 3, step: 0.01, value: 3, exact: true, play: true },
    { key: 'tool', label: 'formula.param.tool', type: 'select', value: 'striction', options: () => TOOLS.map((k) => [k, `formula.tool.${k}`]) },
    { key: 'n', label: 'param.rulings', type: 'range', min: 4, max: 160, step: 1, value: 36, play: true, unless: onlyFor('striction', 'bending', 'development', 'subdivision') },
    { key: 'normals', label: 'striction.param.normals', type: 'checkbox', value: true, unless: onlyFor('striction') },
    { key: 'polygon', label: 'striction.param.polygon', type: 'checkbox', value: true, unless: onlyFor('striction') },
    { key: 'midpoints', label: 'striction.param.midpoints', type: 'checkbox', value: false, unless: onlyFor('striction') },
    { key: 'exact', label: 'striction.param.exact', type: 'checkbox', value: true, unless: onlyFor('striction') },
    { key: 'axis', label: 'striction.param.axis', type: 'checkbox', value: false, unless: onlyFor('striction') },
    { key: 'strip', label: 'param.strip', type: 'checkbox', value: true, unless: onlyFor('striction') },
    { key: 'u', label: 'convergence.param.u', type: 'range', min: -10, max: 10, step: 0.01, value: 0.7, play: true, unless: onlyFor('convergence') },
    { key: 'h0', label: 'convergence.param.h0', type: 'range', min: 0.02, max: 0.8, step: 0.01, value: 0.3, unless: onlyFor('convergence') },
    { key: 'levels', label: 'convergence.param.levels', type: 'range', min: 3, max: 12, step: 1, value: 8, unless: onlyFor('convergence') },
    { key: 't', label: 'isometry.param.t', type: 'range', min: 0, max: 1, step: 0.01, value: 1, play: true, unless: onlyFor('bending') },
    { key: 'scheme', label: 'param.scheme', type: 'select', value: 'four-point', refit: false, options: () => [['four-point', 'formula.scheme.fourPoint'], ['chaikin', 'formula.scheme.chaikin'], ['variational', 'formula.scheme.variational'], ['lines', 'formula.scheme.lines']], unless: onlyFor('subdivision') },
    { key: 'steps', label: 'param.steps', type: 'range', min: 1, max: 4, step: 1, value: 1, play: true, unless: onlyFor('subdivision') },
  ],
  legend: [
    { style: 'ruling', label: 'legend.rulings', when: (p) => p.tool !== 'subdivision' },
    { style: 'normal', label: 'legend.normals', when: (p) => (p.tool === 'striction' && !!p.normals) || p.tool === 'convergence' || p.tool === 'bending' },
    { style: 'striction', label: 'legend.striction', when: (p) => (p.tool === 'striction' && !!p.polygon) || p.tool === 'bending' || p.tool === 'development' },
    { style: 'perpendicularMidpoints', label: 'legend.perpendicularMidpoints', when: (p) => p.tool === 'striction' && !!p.midpoints },
    { style: 'exact', label: 'legend.exactStriction', when: (p) => (p.tool === 'striction' && !!p.exact) || p.tool === 'convergence' },
    { style: 'complexAxis', label: 'legend.complexAxis', when: (p) => p.tool === 'striction' && !!p.axis },
    { style: 'tangent', label: 'convergence.legend.tangent', when: (p) => p.tool === 'convergence' },
    { style: 'given', label: 'formula.legend.given', when: (p) => p.tool === 'subdivision' },
    { style: 'inserted', label: 'formula.legend.inserted', when: (p) => p.tool === 'subdivision' },
  ],
  fieldOf: (option) => FIELDS[option] ?? null,
  create(p, ctx) {
    return scoped((own) => {
      const analytic = own(
        AnalyticSurface.fromFormulas({
          a: [String(p.ax), String(p.ay), String(p.az)],
          e: [String(p.ex), String(p.ey), String(p.ez)],
          u: [String(p.umin), String(p.umax)],
          v: [String(p.vmin), String(p.vmax)],
          closed: !!p.closed,
          parameters: { a: Number(p.a), b: Number(p.b), c: Number(p.c) },
          // German readers write 0,5: a comma between digits is a decimal comma (not in atan2's arguments)
          decimalComma: ctx.lang === 'de',
        }),
      );
      const [uMin, uMax] = [...analytic.parameters(2, { closed: false })];
      const ranges = { uMin, uMax, closed: !!p.closed };
      const n = Number(p.n);
      if (p.tool === 'convergence') return convergenceFigure(own, analytic, { u: Number(p.u), h0: Number(p.h0), levels: Number(p.levels) }, ctx);
      if (p.tool === 'subdivision') return subdivisionFigure(own, analytic, ranges, { n, scheme: String(p.scheme), steps: Number(p.steps) }, ctx);
      if (p.tool === 'bending' || p.tool === 'development') {
        const surface = own(analytic.sample(n, { closed: false }));
        return isometryFigure(own, surface, { layout: p.tool === 'bending' ? 'bend' : 'panels', t: Number(p.t), ghost: true, n }, ctx, 'formula');
      }
      return strictionFigure(own, analytic, ranges, /** @type {any} */ ({ ...p, n }), ctx, 'formula');
    });
  },
});
