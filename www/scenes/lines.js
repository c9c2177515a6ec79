// Beyond the paper: subdivision in the space of lines. Sliding the given endpoints along their
// lines moves the endpoint scheme's surface, but not the line-space scheme's.
import { AnalyticSurface, RuledSurface, kleinDeparture, stripIndices } from '../../pkg/ruledlab.js';
import { defineScene, scoped, bounds } from '../scene.js';
import { KLEIN_PROJECTION } from '../klein-image.js';
import { rulingSet } from '../edit/sets.js';

const RANGES = { hyperboloid: { uMin: 0, uMax: 3 }, helical: { uMin: 0, uMax: 6 }, quartic: { uMin: -1, uMax: 1 } };

/** How far each endpoint slides along its line: a fixed pattern, scaled by `amount` (units of segment length). */
function pattern(/** @type {number} */ n, /** @type {number} */ amount, /** @type {number} */ length) {
  return Float64Array.from(
    { length: 2 * n },
    (_, k) => amount * 0.6 * length * (k % 2 ? Math.cos(1.7 * (k >> 1) + 0.4) : Math.sin(2.3 * (k >> 1) + 1)),
  );
}

export const scene = defineScene({
  id: 'lines',
  title: 'lines.title',
  text: 'lines.text',
  // an edit of the given rulings replaces the slid ones (the surface stays: both schemes are
  // compared with what they make of its own rulings)
  fixed: ['surface', 'slide'],
  params: [
    {
      key: 'surface',
      label: 'param.surface',
      type: 'select',
      value: 'helical',
      options: () => [
        ['helical', 'surface.helical'],
        ['hyperboloid', 'surface.hyperboloid'],
        ['quartic', 'surface.quartic'],
      ],
    },
    { key: 'slide', label: 'lines.param.slide', type: 'range', min: 0, max: 1, step: 0.01, value: 0.6, play: true },
    { key: 'steps', label: 'param.steps', type: 'range', min: 1, max: 3, step: 1, value: 2, play: true },
  ],
  legend: [
    { style: 'given', label: 'lines.legend.given' },
    { style: 'endpointScheme', label: 'lines.legend.endpoints' },
    { style: 'lineScheme', label: 'lines.legend.lines' },
  ],
  create(p, { t, input }) {
    return scoped((own) => {
      const name = /** @type {keyof typeof RANGES} */ (String(p.surface));
      const analytic = own(AnalyticSurface.byName(name));
      const base = own(analytic.sample(9, { ...RANGES[name], closed: false }));
      const length = base.meanLength();
      // the given rulings: the endpoints slid by the pattern, or as the reader moved them
      const edited = input?.rulings;
      const slid = own(edited ? RuledSurface.fromSegments(edited) : base.slide(pattern(9, Number(p.slide), length)));
      /** @type {import('../../pkg/ruledlab.js').SubdivideOptions} */
      const options = { scheme: 'four-point', steps: Number(p.steps) };
      const ends = own(slid.subdivide(options));
      const lines = own(slid.subdivide({ ...options, space: 'lines', length }));
      const ends0 = own(base.subdivide(options));
      const lines0 = own(base.subdivide({ ...options, space: 'lines', length }));
      const endpointTurn = ends0.maxAngleTo(ends);
      const lineTurn = lines0.maxAngleTo(lines);
      // how far the line-space scheme's points leave the Klein quadric before N projects them back
      const given = slid.segments();
      const departure = kleinDeparture(given, options, KLEIN_PROJECTION);
      const before = departure.before[departure.before.length - 1];
      const after = departure.after.reduce((m, x) => Math.max(m, x), 0);
      const endsSeg = ends.segmentsF32();
      const linesSeg = lines.segmentsF32();
      return {
        bounds: bounds(base.segmentsF32(), linesSeg),
        camera: { yaw: -1.3, pitch: 0.45 },
        layers: [
          { kind: 'segments', style: 'given', positions: slid.segmentsF32() },
          { kind: 'segments', style: 'endpointScheme', positions: endsSeg },
          { kind: 'segments', style: 'lineScheme', positions: linesSeg },
          { kind: 'mesh', style: 'endpointStrip', positions: endsSeg, indices: stripIndices(ends.length) },
          { kind: 'mesh', style: 'lineStrip', positions: linesSeg, indices: stripIndices(lines.length) },
        ],
        readouts: [
          { label: 'lines.readout.endpoints', value: endpointTurn, exactZero: true },
          { label: 'lines.readout.lines', value: lineTurn, exactZero: true },
          { label: 'lines.readout.departure', value: before },
          { label: 'lines.readout.departureAfter', value: after, exactZero: true },
        ],
        description: t(edited ? 'lines.describeEdited' : 'lines.describe', {
          surface: t(`surface.${name}`),
          slide: Number(p.slide),
          endpointTurn,
          lineTurn,
        }),
        data: { segments: lines.segments() },
        // beside, on M: the last step's points before N, each joined to its line's point after N,
        // in the image the view draws in (a plain function of the core's: nothing to free)
        klein: (image) => {
          const { points, lines: after1 } = kleinDeparture(given, options, image);
          const back = new Float32Array(2 * points.length);
          for (let i = 0; 3 * i < points.length; i++) {
            back.set(points.subarray(3 * i, 3 * i + 3), 6 * i);
            back.set(after1.subarray(3 * i, 3 * i + 3), 6 * i + 3);
          }
          return {
            layers: [
              { kind: 'segments', style: 'barycentre', positions: back },
              { kind: 'points', style: 'insertedPoint', positions: points },
            ],
            legend: [
              { style: 'insertedPoint', label: 'lines.klein.before' },
              { style: 'barycentre', label: 'lines.klein.back' },
            ],
            description: t('lines.klein.describe', { steps: Number(p.steps), before, after }),
          };
        },
        // the handles: the given rulings' endpoints (Shift slides one along its ruling)
        input: { sets: [rulingSet(slid.segments())], from: t('edit.from.lines', { surface: t(`surface.${name}`) }) },
      };
    });
  },
});
