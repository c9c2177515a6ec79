// Your surface: x(u, v) = a(u) + v·e(u) typed as formulas, with every tool of Sections 2–4 on
// it: the striction polygon against the exact striction curve, the convergence orders,
// bending, the approximate development, and subdivision. The core parses the formulas and
// differentiates them exactly; the formulas live in the link, so a lecturer can link an exercise.
import { AnalyticSurface, fitLine } from '../../pkg/ruledlab.js';
import { defineScene, scoped, schemeParam } from '../scene.js';
import { strictionLayers, exactCurve } from '../layers/striction.js';
import { convergenceLayers } from '../layers/convergence.js';
import { BENDING_TIME, isometryLayers } from '../layers/isometry.js';
import { subdivisionLayers } from '../layers/subdivision.js';
import { CLOSING_GAP, STRAIGHTNESS_MIN_EXTENT, STRAIGHTNESS_SAMPLES } from '../limits.js';
import { SURFACE_PRESETS, formulaFieldOf, formulaParameter, surfaceFields } from '../catalogue.js';

const HYPERBOLOID = surfaceFields('hyperboloid');
const TOOLS = ['striction', 'convergence', 'bending', 'development', 'subdivision'];
/** @param {string[]} tools @returns {(p: import('../scene.js').Params) => string | null} */
const onlyFor =
  (...tools) =>
  (p) =>
    tools.includes(String(p.tool)) ? null : 'formula.reason.tool';

/** A text parameter holding a formula. */
const formula = (/** @type {string} */ key, /** @type {string} */ value) => ({
  key,
  label: `formula.param.${key}`,
  type: /** @type {const} */ ('text'),
  value,
});

/** @typedef {{preset: string, ax: string, ay: string, az: string, ex: string, ey: string, ez: string, umin: string, umax: string, vmin: string, vmax: string, closed: boolean, a: number, b: number, c: number, tool: string, n: number, normals: boolean, polygon: boolean, midpoints: boolean, exact: boolean, axis: boolean, strip: boolean, u: number, h0: number, levels: number, t: number, scheme: string, steps: number}} FormulaParams */

/**
 * The surface of the formula fields (the caller owns it).
 * @param {import('../scene.js').Params} p
 * @param {import('../scene.js').Context} ctx
 */
function analyticOf(p, ctx) {
  return AnalyticSurface.fromFormulas({
    a: [String(p.ax), String(p.ay), String(p.az)],
    e: [String(p.ex), String(p.ey), String(p.ez)],
    u: [String(p.umin), String(p.umax)],
    v: [String(p.vmin), String(p.vmax)],
    closed: !!p.closed,
    parameters: { a: Number(p.a), b: Number(p.b), c: Number(p.c) },
    // 0,5 is a number in every language (a German link opened in English); only a German
    // reader's atan2(1,5) is ambiguous (an English reader's has two arguments)
    decimalComma: ctx.lang === 'de' ? true : 'unambiguous',
  });
}

/**
 * Why "Closed in u" does not fit the surface of the fields, or null: a closed surface follows its
 * last ruling by its first, so the ruling at the end of u must be the one at its start (the same
 * line, either way round: a Möbius band closes too). A surface typed over a preset keeps the
 * preset's "closed" (the hyperboloid's), and a helicoid over [0, 2π] would be joined from its top
 * back to its foot: that is said, not drawn silently.
 * @param {<T extends {free(): void}>(o: T) => T} own   the scene's scope (frees what it makes)
 * @param {import('../../pkg/ruledlab.js').AnalyticSurface} analytic
 * @param {import('../scene.js').Context} ctx
 */
function notClosing(own, analytic, ctx) {
  // the core's pair invariants of the rulings at the two ends of u: one line when they are
  // parallel (or antiparallel) at distance 0
  const ends = own(analytic.sample(2, { closed: false }));
  const { parallel, distance, angle } = ends.invariants({ closed: false });
  // rounding: CLOSING_GAP of the largest coordinate
  const size = Array.from(ends.segments()).reduce((m, x) => Math.max(m, Math.abs(x)), 1);
  const gap = Math.abs(distance[0]);
  if (parallel[0] && gap <= CLOSING_GAP * size) return null;
  const [uMin, uMax] = [...analytic.parameters(2, { closed: false })];
  return ctx.t('formula.problem.notClosed', {
    umin: ctx.format(uMin),
    umax: ctx.format(uMax),
    gap: ctx.format(gap),
    // (a parallel pair at angle 0, not its rounding)
    angle: ctx.format(parallel[0] ? 0 : Math.min(angle[0], Math.PI - angle[0])),
  });
}

/** The u-range of the surface of the formula fields (the fields' own ends, evaluated by the core). */
function rangesOf(
  /** @type {import('../../pkg/ruledlab.js').AnalyticSurface} */ analytic,
  /** @type {import('../scene.js').Params} */ p,
) {
  const [uMin, uMax] = [...analytic.parameters(2, { closed: false })];
  return { uMin, uMax, closed: !!p.closed };
}

export const scene = defineScene({
  id: 'formula',
  title: 'formula.title',
  text: 'formula.text',
  editAsData: true,
  params: [
    {
      key: 'preset',
      label: 'formula.param.preset',
      type: 'select',
      value: 'hyperboloid',
      options: () => SURFACE_PRESETS.map((k) => [k.name, `surface.${k.name}`]),
      sets: (v) => surfaceFields(String(v)),
    },
    formula('ax', String(HYPERBOLOID.ax)),
    formula('ay', String(HYPERBOLOID.ay)),
    formula('az', String(HYPERBOLOID.az)),
    formula('ex', String(HYPERBOLOID.ex)),
    formula('ey', String(HYPERBOLOID.ey)),
    formula('ez', String(HYPERBOLOID.ez)),
    formula('umin', '0'),
    formula('umax', '2*pi'),
    formula('vmin', '-1'),
    formula('vmax', '1'),
    { key: 'closed', label: 'formula.param.closed', type: 'checkbox', value: true },
    formulaParameter('a', 1),
    formulaParameter('b', 2),
    formulaParameter('c', 3),
    {
      key: 'tool',
      label: 'formula.param.tool',
      type: 'select',
      value: 'striction',
      options: () => TOOLS.map((k) => [k, `formula.tool.${k}`]),
    },
    {
      key: 'n',
      label: 'param.rulings',
      type: 'range',
      min: 4,
      max: 160,
      step: 1,
      value: 36,
      play: true,
      unless: onlyFor('striction', 'bending', 'development', 'subdivision'),
    },
    { key: 'normals', label: 'striction.param.normals', type: 'checkbox', value: true, unless: onlyFor('striction') },
    { key: 'polygon', label: 'striction.param.polygon', type: 'checkbox', value: true, unless: onlyFor('striction') },
    {
      key: 'midpoints',
      label: 'striction.param.midpoints',
      type: 'checkbox',
      value: false,
      unless: onlyFor('striction'),
    },
    { key: 'exact', label: 'striction.param.exact', type: 'checkbox', value: true, unless: onlyFor('striction') },
    { key: 'axis', label: 'striction.param.axis', type: 'checkbox', value: false, unless: onlyFor('striction') },
    { key: 'strip', label: 'param.strip', type: 'checkbox', value: true, unless: onlyFor('striction') },
    {
      key: 'u',
      label: 'convergence.param.u',
      type: 'range',
      min: -10,
      max: 10,
      step: 0.01,
      value: 0.7,
      play: true,
      unless: onlyFor('convergence'),
    },
    {
      key: 'h0',
      label: 'convergence.param.h0',
      type: 'range',
      min: 0.02,
      max: 0.8,
      step: 0.01,
      value: 0.3,
      unless: onlyFor('convergence'),
    },
    {
      key: 'levels',
      label: 'convergence.param.levels',
      type: 'range',
      min: 3,
      max: 12,
      step: 1,
      value: 8,
      unless: onlyFor('convergence'),
    },
    { ...BENDING_TIME, unless: onlyFor('bending') },
    schemeParam(
      'four-point',
      () => [
        ['four-point', 'formula.scheme.fourPoint'],
        ['chaikin', 'formula.scheme.chaikin'],
        ['variational', 'formula.scheme.variational'],
        ['lines', 'formula.scheme.lines'],
      ],
      { unless: onlyFor('subdivision') },
    ),
    {
      key: 'steps',
      label: 'param.steps',
      type: 'range',
      min: 1,
      max: 4,
      step: 1,
      value: 1,
      play: true,
      unless: onlyFor('subdivision'),
    },
  ],
  legend: [
    { style: 'ruling', label: 'legend.rulings', when: (p) => p.tool !== 'subdivision' },
    {
      style: 'normal',
      label: 'legend.normals',
      when: (p) => (p.tool === 'striction' && !!p.normals) || p.tool === 'convergence' || p.tool === 'bending',
    },
    {
      style: 'striction',
      label: 'legend.striction',
      when: (p) => (p.tool === 'striction' && !!p.polygon) || p.tool === 'bending' || p.tool === 'development',
    },
    {
      style: 'perpendicularMidpoints',
      label: 'legend.perpendicularMidpoints',
      when: (p) => p.tool === 'striction' && !!p.midpoints,
    },
    { style: 'perpendicularMidpoints', label: 'isometry.legend.envelope', when: (p) => p.tool === 'development' },
    {
      style: 'exact',
      label: 'legend.exactStriction',
      when: (p) => (p.tool === 'striction' && !!p.exact) || p.tool === 'convergence',
    },
    { style: 'complexAxis', label: 'legend.complexAxis', when: (p) => p.tool === 'striction' && !!p.axis },
    { style: 'tangent', label: 'convergence.legend.tangent', when: (p) => p.tool === 'convergence' },
    { style: 'given', label: 'formula.legend.given', when: (p) => p.tool === 'subdivision' },
    { style: 'inserted', label: 'formula.legend.inserted', when: (p) => p.tool === 'subdivision' },
  ],
  fieldOf: formulaFieldOf('a'),
  /** @param {FormulaParams} p */
  exact(p, ctx, kind, samples) {
    return scoped((own) => {
      const analytic = own(analyticOf(p, ctx));
      return exactCurve(analytic, rangesOf(analytic, p), kind, samples);
    });
  },
  /** @param {FormulaParams} p */
  create(p, ctx) {
    return scoped((own) => {
      const analytic = own(analyticOf(p, ctx));
      const ranges = rangesOf(analytic, p);
      const n = Number(p.n);
      if (p.tool === 'convergence')
        return convergenceLayers(own, analytic, { u: Number(p.u), h0: Number(p.h0), levels: Number(p.levels) }, ctx);
      // "Closed in u" on a surface whose ends do not meet (the tools that read it: these two)
      const open = ranges.closed ? notClosing(own, analytic, ctx) : null;
      const also = (/** @type {import('../scene.js').Built} */ b) =>
        open ? { ...b, problems: [open, ...(b.problems ?? [])] } : b;
      if (p.tool === 'subdivision')
        return also(
          subdivisionLayers(own, analytic, ranges, { n, scheme: String(p.scheme), steps: Number(p.steps) }, ctx),
        );
      if (p.tool === 'bending' || p.tool === 'development') {
        const surface = own(analytic.sample(n, { closed: false }));
        return isometryLayers(
          own,
          surface,
          { layout: p.tool === 'bending' ? 'bend' : 'panels', t: Number(p.t), ghost: true, n },
          ctx,
          'formula',
        );
      }
      const built = strictionLayers(own(analytic.sample(p.n, ranges)), analytic, ranges, p, ctx, 'formula');
      // how far the exact striction curve is from a straight line, as a share of its length (an
      // exercise asks for one that is straight; scale-free, so shrinking the surface does not pass)
      let straightness = Number.NaN;
      try {
        const fit = fitLine(exactCurve(analytic, ranges, 'striction', STRAIGHTNESS_SAMPLES).values);
        const size = Math.hypot(...built.bounds.max.map((m, k) => m - built.bounds.min[k]));
        if (fit.extent >= STRAIGHTNESS_MIN_EXTENT * size) straightness = fit.deviation / fit.extent;
      } catch {}
      return also({ ...built, measures: { ...built.measures, 'formula.strictionStraightness': straightness } });
    });
  },
});
