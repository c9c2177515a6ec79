// Propositions 1 and 2: the footpoints converge to the striction point at first order, their
// midpoint at second order; likewise δ and its average; and the common perpendicular tends to
// the central tangent (4). Measured live by the core, plotted log-log.
import { AnalyticSurface, RuledSurface } from '../../pkg/ruledlab.js';
import { defineScene, scoped, bounds } from '../scene.js';
import { convergenceLayers, convergenceSample, sampleLayers } from '../layers/convergence.js';
import { surfaceOptions } from '../catalogue.js';
import { parallelProblems, rulingSet, rulingValues } from '../edit/sets.js';

/**
 * The reader's edit of the three rulings: their common perpendiculars, footpoints and striction
 * point, and δ. The orders need the exact surface, which an edit does not have.
 * @param {import('../../pkg/ruledlab.js').RuledSurface} sample
 * @param {import('../scene.js').Context} ctx
 * @returns {import('../scene.js').Built}
 */
function editedSample(sample, { t }) {
  const seg = sample.segmentsF32();
  const inv = sample.invariants();
  return {
    bounds: bounds(seg),
    camera: { yaw: -0.9, pitch: 0.35 },
    layers: sampleLayers(seg, inv),
    readouts: [
      { label: 'convergence.readout.delta01', value: inv.distribution[0] },
      { label: 'convergence.readout.delta12', value: inv.distribution[1] },
      { label: 'convergence.readout.deltaMeanEdited', value: inv.distributionMean[0] },
    ],
    note: t('convergence.editedNote'),
    problems: parallelProblems(inv.parallel, 3, t),
    description: t('convergence.describeEdited', { delta: inv.distributionMean[0] }),
  };
}

export const scene = defineScene({
  id: 'convergence',
  title: 'convergence.title',
  text: 'convergence.text',
  paper: true,
  // an edit of the three rulings replaces the surface they sample
  fixed: ['surface', 'u', 'h0', 'levels'],
  params: [
    {
      key: 'surface',
      label: 'param.surface',
      type: 'select',
      value: 'hyperboloid',
      options: surfaceOptions([
        'hyperboloid',
        'quartic',
        'helical',
        'pluecker-conoid',
        'hyperbolic-paraboloid',
        'helix-tangent',
      ]),
    },
    { key: 'u', label: 'convergence.param.u', type: 'range', min: -1, max: 3, step: 0.01, value: 0.7, play: true },
    {
      key: 'h0',
      label: 'convergence.param.h0',
      type: 'range',
      min: 0.05,
      max: 0.8,
      step: 0.01,
      value: 0.4,
      play: true,
    },
    { key: 'levels', label: 'convergence.param.levels', type: 'range', min: 3, max: 12, step: 1, value: 8 },
  ],
  legend: [
    { style: 'rulingBold', label: 'convergence.legend.rulings' },
    { style: 'normal', label: 'legend.normals' },
    { style: 'strictionPoint', label: 'convergence.legend.midpoint' },
    { style: 'exact', label: 'legend.exactStriction' },
    { style: 'tangent', label: 'convergence.legend.tangent' },
  ],
  create(p, ctx) {
    return scoped((own) => {
      const name = String(p.surface);
      const analytic = own(AnalyticSurface.byName(name));
      const q = { u: Number(p.u), h0: Number(p.h0), levels: Number(p.levels) };
      const edited = ctx.input?.rulings;
      const sample = edited ? own(RuledSurface.fromSegments(edited)) : convergenceSample(own, analytic, q);
      const built = edited ? editedSample(sample, ctx) : convergenceLayers(own, analytic, q, ctx);
      // the handles: the endpoints of the three rulings
      const from = ctx.t('edit.from.convergence', { surface: ctx.t(`surface.${name}`), u: q.u });
      // (three rulings: their invariants cost nothing beside the figure's)
      const values = rulingValues(sample.invariants(), 3, ctx.t);
      return { ...built, input: { sets: [rulingSet(sample.segments())], from, values } };
    });
  },
});
