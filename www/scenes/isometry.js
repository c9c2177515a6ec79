// Section 3, Figs. 4–6: discrete Minding isometries. A slider bends the hinge chain from the
// surface (t = 0) to its isometric conoidal model (t = 1); "three panels" shows Fig. 6:
// surface, conoidal model and approximate development side by side. Everything is drawn in
// the reference frame of the conoidal model (x = e_0, z = n_{0,1}), which the core supplies.
import { AnalyticSurface, RuledSurface } from '../../pkg/ruledlab.js';
import { defineScene, scoped } from '../scene.js';
import { isometryFigure, middleRadius } from '../figures/isometry.js';
import { surfaceOptions, rangesOf } from '../catalogue.js';

/** Open parameter ranges that make good figures (the project's choice: the paper gives no data). */
/**
 * The rulings of an edited cone that miss its vertex, in a sentence: by how much, or that every
 * ruling passes through it (within 10⁻⁹ of the cone's size, rounding).
 * @param {Float64Array} segments   a_i, b_i per ruling
 * @param {Float64Array} vertex
 * @param {import('../scene.js').Context} ctx
 */
function offVertex(segments, vertex, ctx) {
  /** @type {Array<[number, number]>} */
  const off = [];
  let size = 0;
  for (let i = 0; 6 * i + 5 < segments.length; i++) {
    const a = [0, 1, 2].map((k) => segments[6 * i + k] - vertex[k]);
    const e = [0, 1, 2].map((k) => segments[6 * i + 3 + k] - segments[6 * i + k]);
    const length = Math.hypot(...e);
    // |a × e| / |e|: the distance of the vertex from the ruling's line
    const c = [a[1] * e[2] - a[2] * e[1], a[2] * e[0] - a[0] * e[2], a[0] * e[1] - a[1] * e[0]];
    const distance = length > 0 ? Math.hypot(...c) / length : Math.hypot(...a);
    size = Math.max(size, Math.hypot(...a), length);
    off.push([i, distance]);
  }
  const missing = off.filter(([, d]) => d > 1e-9 * size);
  if (!missing.length) return ctx.t('isometry.describe.vertex.all');
  const most = ctx.format(Math.max(...missing.map(([, d]) => d)));
  if (missing.length === 1) return ctx.t('isometry.describe.vertex.one', { i: String(missing[0][0]), distance: most });
  return ctx.t('isometry.describe.vertex.some', { list: missing.map(([i]) => i).join(', '), distance: most });
}

const RANGES = {
  hyperboloid: { uMin: 0, uMax: 2.4, closed: false },
  helical: { uMin: 0, uMax: 9, closed: false },
  'helical-orthogonal': { uMin: 0, uMax: 9, closed: false },
  'pluecker-conoid': { uMin: 0.1, uMax: 1.5, closed: false },
  cone: { uMin: 0, uMax: 4.5, closed: false },
  'helix-tangent': { uMin: 0, uMax: 5, closed: false },
};

/** @typedef {{surface: string, layout: string, n: number, t: number, ghost: boolean}} IsometryParams */

export const scene = defineScene({
  id: 'isometry',
  title: 'isometry.title',
  text: 'isometry.text',
  paper: true,
  // an edit of the rulings replaces the sampled surface
  fixed: ['surface', 'n'],
  params: [
    {
      key: 'surface',
      label: 'param.surface',
      type: 'select',
      value: 'quartic',
      options: surfaceOptions([
        'quartic',
        'helical',
        'helical-orthogonal',
        'hyperboloid',
        'hyperbolic-paraboloid',
        'pluecker-conoid',
        'helix-tangent',
        'cone',
      ]),
    },
    {
      key: 'layout',
      label: 'isometry.param.layout',
      type: 'select',
      value: 'bend',
      options: () => [
        ['bend', 'isometry.layout.bend'],
        ['panels', 'isometry.layout.panels'],
      ],
    },
    { key: 'n', label: 'param.rulings', type: 'range', min: 4, max: 120, step: 1, value: 24, play: true },
    {
      key: 't',
      label: 'isometry.param.t',
      type: 'range',
      min: 0,
      max: 1,
      step: 0.01,
      value: 1,
      play: true,
      unless: (p) => (p.layout === 'panels' ? 'isometry.reason.panels' : null),
    },
    {
      key: 'ghost',
      label: 'isometry.param.ghost',
      type: 'checkbox',
      value: true,
      unless: (p) => (p.layout === 'panels' ? 'isometry.reason.panels' : p.t === 0 ? 'isometry.reason.flat' : null),
    },
  ],
  legend: [
    { style: 'ruling', label: 'legend.rulings' },
    { style: 'striction', label: 'isometry.legend.striction' },
    { style: 'perpendicularMidpoints', label: 'isometry.legend.envelope', when: (p) => p.layout === 'panels' },
    { style: 'normal', label: 'legend.normals', when: (p) => p.layout === 'bend' },
    {
      style: 'ghost',
      label: 'isometry.legend.ghost',
      when: (p) => p.layout === 'bend' && !!p.ghost && Number(p.t) > 0,
    },
  ],
  /** @param {IsometryParams} p */
  create(p, ctx) {
    return scoped((own) => {
      const name = String(p.surface);
      const analytic = own(AnalyticSurface.byName(name));
      const ranges = rangesOf(name, RANGES[/** @type {keyof typeof RANGES} */ (name)] ?? {});
      const n = Number(p.n);
      const edited = ctx.input?.rulings;
      const surface = own(edited ? RuledSurface.fromSegments(edited) : analytic.sample(n, ranges));
      // Fig. 5: ρ with twice the spacing halved, to show its order where the caption holds
      const finer =
        name === 'helical-orthogonal' && !edited
          ? { n: 2 * n - 1, radius: middleRadius(own(analytic.sample(2 * n - 1, ranges))) }
          : null;
      const from = ctx.t('edit.from.surface', { surface: ctx.t(`surface.${name}`), n });
      const built = isometryFigure(own, surface, p, ctx, name, finer, from);
      // the captions' claims are about the built-in surfaces
      if (!edited) return built;
      const description = ctx.t('edit.describe', { description: built.description });
      // an edited cone: which rulings miss its vertex, as the eye sees at once (the exercise
      // "Make the cone developable again" starts with one lifted)
      const vertex = name === 'cone' ? offVertex(edited, analytic.striction(new Float64Array([0])), ctx) : '';
      return { ...built, claims: [], description: vertex ? `${description} ${vertex}` : description };
    });
  },
});
