// Section 2, Figs. 2–3 (Example 1): a discrete ruled surface with its common perpendiculars,
// the striction polygon m_i of Proposition 2 and, switchable, Fig. 3's polygon of the
// midpoints of the common perpendiculars, against the exact striction curve.
import { AnalyticSurface, RuledSurface } from '../../pkg/ruledlab.js';
import { defineScene, scoped } from '../scene.js';
import { strictionLayers, exactCurve } from '../layers/striction.js';
import { surfaceOptions, rangesOf } from '../catalogue.js';

/** @typedef {{surface: string, n: number, strip: boolean, normals: boolean, polygon: boolean, midpoints: boolean, exact: boolean, axis: boolean}} StrictionParams */

export const scene = defineScene({
  id: 'striction',
  title: 'striction.title',
  text: 'striction.text',
  paper: true,
  // an edit of the rulings replaces the sampled surface (and its exact striction curve)
  fixed: ['surface', 'n', 'exact'],
  params: [
    { key: 'surface', label: 'param.surface', type: 'select', value: 'hyperboloid', options: surfaceOptions() },
    { key: 'n', label: 'param.rulings', type: 'range', min: 6, max: 160, step: 1, value: 36, play: true },
    { key: 'strip', label: 'param.strip', type: 'checkbox', value: true },
    { key: 'normals', label: 'striction.param.normals', type: 'checkbox', value: true },
    { key: 'polygon', label: 'striction.param.polygon', type: 'checkbox', value: true },
    { key: 'midpoints', label: 'striction.param.midpoints', type: 'checkbox', value: false },
    { key: 'exact', label: 'striction.param.exact', type: 'checkbox', value: false },
    { key: 'axis', label: 'striction.param.axis', type: 'checkbox', value: false },
  ],
  legend: [
    { style: 'ruling', label: 'legend.rulings' },
    { style: 'normal', label: 'legend.normals', when: (p) => !!p.normals },
    { style: 'striction', label: 'legend.striction', when: (p) => !!p.polygon },
    { style: 'perpendicularMidpoints', label: 'legend.perpendicularMidpoints', when: (p) => !!p.midpoints },
    { style: 'exact', label: 'legend.exactStriction', when: (p) => !!p.exact },
    { style: 'complexAxis', label: 'legend.complexAxis', when: (p) => !!p.axis },
  ],
  /** @param {StrictionParams} p */
  exact(p, _ctx, kind, samples) {
    return scoped((own) => {
      const name = String(p.surface);
      return exactCurve(own(AnalyticSurface.byName(name)), rangesOf(name), kind, samples);
    });
  },
  /** @param {StrictionParams} p */
  create(p, ctx) {
    return scoped((own) => {
      const name = String(p.surface);
      const analytic = own(AnalyticSurface.byName(name));
      const ranges = rangesOf(name);
      const edited = ctx.input?.rulings;
      const surface = own(edited ? RuledSurface.fromSegments(edited) : analytic.sample(p.n, ranges));
      // the handles: every ruling's endpoints a_i, b_i
      const from = ctx.t('edit.from.surface', { surface: ctx.t(`surface.${name}`), n: p.n });
      return strictionLayers(surface, edited ? null : analytic, ranges, p, ctx, name, true, from);
    });
  },
});
