// The subdivision figure (Section 4): a sampling of a surface refined by a strip scheme, the
// old rulings and the inserted ones, and how far the inserted ones are from the exact surface.
// Drawn by "Your surface".
import { stripIndices } from '../../pkg/ruledlab.js';
import { bounds } from '../scene.js';
import { FINE_LINES } from '../limits.js';

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
export function subdivisionLayers(own, analytic, ranges, p, { t }) {
  const surface = own(analytic.sample(p.n, { ...ranges, closed: false }));
  const steps = Number(p.steps);
  /** @type {import('../../pkg/ruledlab.js').SubdivideOptions} */
  const options =
    p.scheme === 'lines'
      ? { scheme: 'four-point', space: 'lines', steps }
      : { scheme: /** @type {import('../../pkg/ruledlab.js').SubdivideOptions['scheme']} */ (p.scheme), steps };
  const refined = own(surface.subdivide(options));
  const stride = 2 ** p.steps;
  const distance = analytic.insertedDistance(refined, stride, ranges.uMin, ranges.uMax);
  const seg = refined.segmentsF32();
  return {
    bounds: bounds(seg),
    camera: { yaw: -1.2, pitch: 0.45 },
    layers: [
      { kind: 'segments', style: 'given', positions: surface.segmentsF32() },
      {
        kind: 'segments',
        style: refined.length > FINE_LINES ? 'insertedFine' : 'inserted',
        positions: refined.insertedF32(stride),
      },
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
