// The convergence figure (Propositions 1 and 2): the discrete invariants of three rulings around
// u against the exact ones, and the measured orders plotted log-log. Drawn by the convergence
// scene and "Your surface".
import { bounds, f32 } from '../scene.js';
import { logLogPlot } from '../diagrams/plot.js';
import { EXACT_ZERO } from '../limits.js';

const SERIES = [
  ['footpoint', 'convergence.series.footpoint'],
  ['midpoint', 'convergence.series.midpoint'],
  ['distribution', 'convergence.series.distribution'],
  ['distributionMean', 'convergence.series.distributionMean'],
  ['centralNormal', 'convergence.series.centralNormal'],
];

/**
 * The sample's own layers: its rulings, their common perpendiculars with the footpoints, and
 * the striction points (what the scene draws of an edited sample too).
 * @param {Float32Array} seg
 * @param {{footpoints: Float64Array, striction: Float64Array}} inv
 * @returns {import('../scene.js').Layer[]}
 */
export function sampleLayers(seg, inv) {
  return [
    { kind: 'segments', style: 'rulingBold', positions: seg },
    { kind: 'segments', style: 'normal', positions: f32(inv.footpoints) },
    { kind: 'points', style: 'foot', positions: f32(inv.footpoints) },
    { kind: 'points', style: 'strictionPoint', positions: f32(inv.striction) },
  ];
}

/**
 * The three rulings at u − h₀, u, u + h₀ that the figure draws: short segments around their
 * striction points.
 * @param {<O extends {free(): void}>(o: O) => O} own
 * @param {import('../../pkg/ruledlab.js').AnalyticSurface} analytic
 * @param {{u: number, h0: number}} p
 */
export function convergenceSample(own, analytic, p) {
  const H = Math.min(p.h0, 1);
  const sampled = own(analytic.sample(3, { uMin: p.u - H, uMax: p.u + H, closed: false }));
  return own(sampled.recut(Math.max(4 * H, 0.6)));
}

/**
 * The convergence figure of an analytic surface at parameter u: shared with "Your surface".
 * @param {<O extends {free(): void}>(o: O) => O} own
 * @param {import('../../pkg/ruledlab.js').AnalyticSurface} analytic
 * @param {{u: number, h0: number, levels: number}} p
 * @param {import('../scene.js').Context} ctx
 * @returns {import('../scene.js').Built}
 */
export function convergenceLayers(own, analytic, p, { t }) {
  const H = Math.min(p.h0, 1);
  const study = analytic.convergence({ u: p.u, h0: H, levels: p.levels });
  const sample = convergenceSample(own, analytic, p);
  const seg = sample.segmentsF32();
  const inv = sample.invariants();
  const at = new Float64Array([p.u]);
  const exact = analytic.striction(at);
  const e3 = analytic.centralTangent(at);
  const reach = Math.max(2 * H, 0.4);
  const tangent = new Float32Array([0, 1, 2, 0, 1, 2].map((c, k) => exact[c] + (k < 3 ? -reach : reach) * e3[c]));
  const curve = analytic.striction(Float64Array.from({ length: 61 }, (_, k) => p.u - H + (2 * H * k) / 60));
  const pick = (/** @type {string} */ name) =>
    /** @type {import('../../pkg/ruledlab.js').ConvergenceSeries} */ (study.series.find((s) => s.name === name));
  const order = (/** @type {string} */ name) =>
    pick(name).errors.every((x) => x < EXACT_ZERO) ? 'readout.exact' : pick(name).fittedOrder;
  const shown = SERIES.slice(0, 4).filter(([name]) => pick(name).errors.some((x) => x >= EXACT_ZERO));
  return {
    bounds: bounds(seg),
    camera: { yaw: -0.9, pitch: 0.35 },
    layers: [
      ...sampleLayers(seg, inv),
      { kind: 'polyline', style: 'exact', positions: f32(curve) },
      { kind: 'segments', style: 'tangent', positions: tangent },
      { kind: 'points', style: 'exactPoint', positions: f32(exact) },
    ],
    diagram: () =>
      logLogPlot(document, {
        x: study.steps,
        series: shown.map(([name, label]) => ({
          name: t(label, { order: pick(name).fittedOrder }),
          y: pick(name).errors,
        })),
        slopes: [1, 2],
        xLabel: t('convergence.plot.x'),
        yLabel: t('convergence.plot.y'),
        title: t('convergence.plot.title'),
        slopeLabel: (k) => t('convergence.plot.slope', { k }),
      }),
    readouts: [
      { label: 'convergence.readout.footpoint', value: order('footpoint') },
      { label: 'convergence.readout.midpoint', value: order('midpoint') },
      { label: 'convergence.readout.delta', value: order('distribution') },
      { label: 'convergence.readout.deltaMean', value: order('distributionMean') },
      { label: 'convergence.readout.normal', value: order('centralNormal') },
    ],
    description: t('convergence.describe', {
      footpoint: typeof order('footpoint') === 'number' ? order('footpoint') : t('readout.exact'),
      midpoint: typeof order('midpoint') === 'number' ? order('midpoint') : t('readout.exact'),
      u: p.u,
      h0: H,
      levels: p.levels,
    }),
  };
}
