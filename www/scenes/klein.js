// Beyond the paper: the Klein quadric. The rulings of a surface of the catalogue as points of the
// Klein quadric M in P⁵, drawn in the 3D image q = cos α x + sin α R_β y the reader steers (the
// core's klein module; the book's chapter "The Klein quadric"): the polygon of the points with
// the Klein form Ω of consecutive rulings by sign (Ω = −h sin φ: 0 where they meet), the image of
// M (the shell between two spheres), the conic of a regulus and the residual of a linear complex.
// The surface itself stands beside, scaled.
import { AnalyticSurface, kleinView } from '../../pkg/ruledlab.js';
import { defineScene, scoped } from '../scene.js';
import { surfaceOptions, rangesOf } from '../catalogue.js';

/** The surfaces offered: a regulus, helical surfaces, developables (torsal at every step), a conoid. */
const SOURCES = ['hyperboloid', 'helicoid', 'helical', 'cone', 'helix-tangent', 'quartic', 'hyperbolic-paraboloid'];

/** Where the surface in space stands: its centre (the origin of space) left of the image, and its radius there. */
const SPACE_AT = -3.2;
const SPACE_RADIUS = 1.3;

/** @typedef {{surface: string, n: number, mix: number, turn: number, unit: number, conic: boolean, space: boolean, mark: number}} KleinParams */

export const scene = defineScene({
  id: 'klein',
  title: 'klein.title',
  text: 'klein.text',
  params: [
    { key: 'surface', label: 'param.surface', type: 'select', value: 'hyperboloid', options: surfaceOptions(SOURCES) },
    { key: 'n', label: 'param.rulings', type: 'range', min: 6, max: 80, step: 1, value: 24, play: true },
    { key: 'mix', label: 'klein.param.mix', type: 'range', min: 0, max: 90, step: 1, value: 30, play: true },
    { key: 'turn', label: 'klein.param.turn', type: 'range', min: 0, max: 360, step: 1, value: 90, play: true },
    { key: 'unit', label: 'klein.param.unit', type: 'range', min: 0.25, max: 4, step: 0.05, value: 1, play: true },
    { key: 'conic', label: 'klein.param.conic', type: 'checkbox', value: true },
    { key: 'space', label: 'klein.param.space', type: 'checkbox', value: true },
    { key: 'mark', label: 'klein.param.mark', type: 'range', min: 0, max: 79, step: 1, value: 0, play: true },
  ],
  legend: [
    { style: 'givenPoint', label: 'klein.legend.points' },
    { style: 'lineScheme', label: 'klein.legend.positive' },
    { style: 'endpointScheme', label: 'klein.legend.negative' },
    { style: 'torsal', label: 'klein.legend.torsal' },
    { style: 'level', label: 'klein.legend.outline' },
    { style: 'conic', label: 'klein.legend.conic', when: (p) => !!p.conic },
  ],
  /** @param {KleinParams} p */
  create(p, { t }) {
    return scoped((own) => {
      const name = String(p.surface);
      const ranges = rangesOf(name);
      const surface = own(own(AnalyticSurface.byName(name)).sample(Number(p.n), ranges));
      const segments = surface.segmentsF32();
      const k = kleinView(surface.segments(), {
        mix: Number(p.mix),
        turn: Number(p.turn),
        unit: Number(p.unit),
        closed: ranges.closed,
      });
      /** @type {import('../scene.js').Layer[]} */
      const layers = [
        { kind: 'polyline', style: 'level', positions: k.outline },
        { kind: 'segments', style: 'lineScheme', positions: k.positive },
        { kind: 'segments', style: 'endpointScheme', positions: k.negative },
        { kind: 'segments', style: 'torsal', positions: k.torsal },
        { kind: 'points', style: 'givenPoint', positions: k.points },
      ];
      const conic = p.conic && k.conic.length > 0;
      if (conic) layers.push({ kind: 'polyline', style: 'conic', positions: k.conic, closed: true });
      // the surface in space, about its own origin (where the moments are taken), scaled to stand beside
      let extent = 0;
      for (const x of segments) extent = Math.max(extent, Math.abs(x));
      const s = SPACE_RADIUS / (extent || 1);
      const transform = new Float32Array([s, 0, 0, 0, 0, s, 0, 0, 0, 0, s, 0, SPACE_AT, 0, 0, 1]);
      if (p.space) layers.push({ kind: 'segments', style: 'ruling', positions: segments, transform });
      // the marked ruling R_i, bold in space and red on M (i up to the last ruling)
      const i = Math.min(Number(p.mark), Number(p.n) - 1);
      if (p.space)
        layers.push({ kind: 'segments', style: 'rulingBold', positions: segments.slice(6 * i, 6 * i + 6), transform });
      layers.push({ kind: 'points', style: 'strictionPoint', positions: k.points.slice(3 * i, 3 * i + 3) });
      const [, outer] = k.radii;
      const r = Math.max(outer, SPACE_RADIUS);
      const box = { min: [p.space ? SPACE_AT - SPACE_RADIUS : -outer, -r, -r], max: [outer, r, r] };
      /** @type {import('../scene.js').Readout[]} */
      const readouts = [
        { label: 'klein.readout.residual', value: k.maxResidual, exactZero: true },
        { label: 'klein.readout.torsal', value: `${k.torsalSteps} / ${k.omega.length}` },
        { label: 'klein.readout.least', value: k.leastOmega, exactZero: true },
        {
          label: 'klein.readout.marked',
          value: i < k.omega.length ? k.omega[i] : 'klein.readout.noStep',
          exactZero: true,
        },
        {
          label: 'klein.readout.plane',
          value: Number.isFinite(k.planeDistance) ? k.planeDistance : 'klein.readout.noPlane',
          exactZero: true,
        },
        { label: 'klein.readout.complex', value: k.complexResidual, exactZero: true },
      ];
      return {
        bounds: box,
        camera: { yaw: -0.5, pitch: 0.35 },
        layers,
        readouts,
        description: [
          t('klein.describe', {
            surface: t(`surface.${name}`),
            n: Number(p.n),
            mix: Number(p.mix),
            turn: Number(p.turn),
            unit: Number(p.unit),
            inner: k.radii[0],
            outer,
            torsal: k.torsalSteps,
            steps: k.omega.length,
            least: k.leastStep,
            omega: k.leastOmega,
            residual: k.maxResidual,
          }),
          conic ? t('klein.describe.conic', { plane: k.planeDistance }) : p.conic ? t('klein.describe.noConic') : '',
          p.space ? t('klein.describe.space', { at: SPACE_AT }) : '',
          t('klein.describe.mark', { i }),
        ]
          .filter((x) => x)
          .join(' '),
        measures: { 'klein.leastStep': k.leastStep, 'klein.leastOmega': k.leastOmega },
        // the three rulings span no conic (the description says so): none in the legend either
        ...(p.conic && !conic ? { legendOff: ['klein.legend.conic'] } : {}),
        data: { segments: surface.segments() },
      };
    });
  },
});
