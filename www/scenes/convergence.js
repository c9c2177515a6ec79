// Propositions 1 and 2: the footpoints converge to the striction point at first order, their
// midpoint at second order; likewise δ and its average; and the common perpendicular tends to
// the central tangent (4). Measured live by the core, plotted log-log.
import { AnalyticSurface } from '../../pkg/ruledlab.js';
import { defineScene, scoped } from '../scene.js';
import { convergenceFigure } from '../figures/convergence.js';
import { surfaceOptions } from '../catalogue.js';

export const scene = defineScene({
  id: 'convergence',
  title: 'convergence.title',
  text: 'convergence.text',
  paper: true,
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
      const analytic = own(AnalyticSurface.byName(String(p.surface)));
      return convergenceFigure(own, analytic, { u: Number(p.u), h0: Number(p.h0), levels: Number(p.levels) }, ctx);
    });
  },
});
