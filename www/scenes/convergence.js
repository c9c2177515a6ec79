// Propositions 1 and 2: the footpoints converge to the striction point at first order, their
// midpoint at second order; likewise δ and its average. Measured live, plotted log-log.
import { AnalyticSurface } from '../../pkg/ruledlab.js';
import { LineBatch } from '../gl/lines.js';
import { PointBatch } from '../gl/points.js';
import { bounds } from '../math.js';
import { logLogPlot } from '../plot.js';
import { COLORS } from '../theme.js';

const GENERIC = [['hyperboloid', 'Hyperboloid of Example 1'], ['quartic', 'Quartic surface of Example 3'], ['helical', 'Ruled helical surface'], ['pluecker-conoid', 'Plücker\u2019s conoid']];

export const scene = {
  id: 'convergence',
  title: 'Convergence orders (Propositions 1–2)',
  params: [
    { key: 'surface', label: 'Surface', type: 'select', value: 'hyperboloid', options: () => GENERIC },
    { key: 'u', label: 'Parameter u', type: 'range', min: -1, max: 3, step: 0.01, value: 0.7 },
    { key: 'h0', label: 'Largest step H₀', type: 'range', min: 0.05, max: 0.8, step: 0.01, value: 0.4 },
    { key: 'levels', label: 'Halvings', type: 'range', min: 3, max: 12, step: 1, value: 8 },
  ],
  text: `
<h2>How fast the discrete invariants converge</h2>
<p>Take the rulings <i>R</i>(u − H), <i>R</i>(u), <i>R</i>(u + H) of an analytic surface and shrink H.
Proposition 1: the footpoint <i>f</i><sub>i,i+1</sub> tends to the striction point s(u) and
<i>δ</i><sub>i,i+1</sub> = h/φ to the distribution parameter, both with errors proportional to H
(slope 1 in the plot). Proposition 2: the midpoint of the two footpoints on <i>R</i>(u) and the
average of the two δ's are far better: their first-order errors cancel, leaving errors
proportional to H² (slope 2). The plot is measured, not drawn from the formulas.</p>
<p>Try the helical surface: there the two footpoints are exactly symmetric about s(u), so the
midpoint is exact (its curve drops to rounding), and δ is second order because the discrete δ is
an even function of H. On Plücker's conoid the footpoints lie on the axis exactly.</p>`,

  create(p) {
    const analytic = AnalyticSurface.byName(p.surface);
    const study = analytic.convergence({ u: p.u, h0: Math.min(p.h0, 1), levels: p.levels });
    const H = p.h0;
    const sampled = analytic.sample(3, { uMin: p.u - H, uMax: p.u + H, closed: false });
    const sample = sampled.recut(Math.max(4 * H, 0.6)); // short segments around the striction points
    sampled.free();
    const seg = sample.segmentsF32();
    const inv = sample.invariants();
    const exact = analytic.striction(new Float64Array([p.u]));
    const curve = analytic.striction(Float64Array.from({ length: 60 }, (_, k) => p.u - H + (2 * H * k) / 59));
    sample.free();
    analytic.free();
    const pick = (name) => study.series.find((s) => s.name === name);
    const figure = logLogPlot({
      x: study.steps,
      series: ['footpoint', 'midpoint', 'distribution', 'distributionMean'].map((name) => ({ name: `${name} (${pick(name).fittedOrder.toFixed(2)})`, y: pick(name).errors })),
      slopes: [1, 2],
      xLabel: 'step H',
      yLabel: 'error',
    });
    const curveSegs = new Float32Array(6 * 59);
    for (let k = 0; k < 59; k++) curveSegs.set(curve.subarray(3 * k, 3 * k + 6), 6 * k);
    return {
      bounds: bounds(seg),
      camera: { yaw: -0.9, pitch: 0.35 },
      figure,
      readout: {
        footpointOrder: pick('footpoint').fittedOrder,
        midpointOrder: pick('midpoint').fittedOrder,
        deltaOrder: pick('distribution').fittedOrder,
        deltaMeanOrder: pick('distributionMean').fittedOrder,
      },
      readoutLabels: { footpointOrder: 'order of fᵢ,ᵢ₊₁', midpointOrder: 'order of the midpoint', deltaOrder: 'order of δ', deltaMeanOrder: 'order of the averaged δ' },
      build(gl) {
        return [
          new LineBatch(gl, seg, { color: COLORS.ruling, width: 2 }),
          new LineBatch(gl, new Float32Array(inv.footpoints), { color: COLORS.normal, width: 2.6 }),
          new LineBatch(gl, curveSegs, { color: COLORS.exact, width: 3 }),
          new PointBatch(gl, new Float32Array(inv.footpoints), { color: COLORS.foot, size: 8 }),
          new PointBatch(gl, new Float32Array(inv.striction), { color: COLORS.striction, size: 10 }),
          new PointBatch(gl, new Float32Array(exact), { color: COLORS.exact, size: 10 }),
        ];
      },
    };
  },

  legend: [
    ['ruling', 'R(u − H), R(u), R(u + H) for the largest H'],
    ['normal', 'common perpendiculars and footpoints'],
    ['striction', 'midpoint of the footpoints on R(u)'],
    ['exact', 'exact striction curve s'],
  ],
};
