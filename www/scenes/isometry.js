// Section 3, Figs. 4–6: discrete Minding isometries. A slider bends the hinge chain from the
// surface (t = 0) to its isometric conoidal model (t = 1); "three panels" shows Fig. 6:
// surface, conoidal model and approximate development side by side. Everything is drawn in
// the reference frame of the conoidal model (x = e_0, z = n_{0,1}), which the core supplies.
import { AnalyticSurface, RuledSurface } from '../../pkg/ruledlab.js';
import { defineScene, scoped } from '../scene.js';
import { BENDING_TIME, isometryLayers, middleRadius } from '../layers/isometry.js';
import { surfaceOptions, rangesOf } from '../catalogue.js';

/** Open parameter ranges that make good figures (the project's choice: the paper gives no data). */
/**
 * An edited cone in a sentence, from the core's signed distances h of consecutive rulings (on a
 * cone each pair meets, h = 0): the rulings that meet neither neighbour (one lifted off the vertex
 * is one), else the pairs that do not meet, else that every pair meets — what the eye sees at once.
 * @param {import('../../pkg/ruledlab.js').RuledSurface} surface
 * @param {boolean} closed
 * @param {import('../scene.js').Context} ctx
 */
function coneSentence(surface, closed, ctx) {
  const { distance } = surface.invariants({ closed });
  const n = surface.length;
  // rounding: 10⁻⁹ of the largest coordinate
  const size = Array.from(surface.segments()).reduce((m, x) => Math.max(m, Math.abs(x)), 1);
  const apart = Array.from(distance, (h) => Math.abs(h) > 1e-9 * size);
  const worst = ctx.format(Array.from(distance).reduce((m, h) => Math.max(m, Math.abs(h)), 0));
  const pair = (/** @type {number} */ k) => (k >= 0 ? apart[k] : closed && apart[n - 1]);
  const lone = Array.from({ length: n }, (_, i) => i).filter(
    (i) => pair(i - 1) && (i < apart.length ? apart[i] : false),
  );
  if (lone.length === 1) return ctx.t('isometry.describe.cone.one', { i: String(lone[0]), distance: worst });
  if (lone.length) return ctx.t('isometry.describe.cone.some', { list: lone.join(', '), distance: worst });
  const pairs = apart.flatMap((a, k) => (a ? [`(${k}, ${(k + 1) % n})`] : []));
  if (pairs.length) return ctx.t('isometry.describe.cone.pairs', { list: pairs.join(', '), distance: worst });
  return ctx.t('isometry.describe.cone.all');
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
    { ...BENDING_TIME, unless: (p) => (p.layout === 'panels' ? 'isometry.reason.panels' : null) },
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
      const built = isometryLayers(own, surface, p, ctx, name, finer, from);
      // the captions' claims are about the built-in surfaces
      if (!edited) return built;
      const description = ctx.t('edit.describe', { description: built.description });
      // an edited cone: which ruling is out of place, as the eye sees at once (the exercise
      // "Make the cone developable again" starts with one lifted)
      const cone = name === 'cone' ? coneSentence(surface, ranges.closed, ctx) : '';
      return { ...built, claims: [], description: cone ? `${description} ${cone}` : description };
    });
  },
});
