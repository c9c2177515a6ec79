// Section 4, Figs. 7–8: Chaikin's corner cutting and the four-point scheme (8) on a polygon,
// step by step, with the tension w on a slider or typed exactly (Fig. 8 uses w = 1/13).
import { subdividePolygon } from '../../pkg/ruledlab.js';
import { defineScene, bounds, f32 } from '../scene.js';
import { pointSet } from '../edit/sets.js';

/** The control polygon: a lopsided star in the plane z = 0 (the project's choice; the paper gives no data). */
const POLYGON = new Float64Array([
  0, 0, 0, 2, 3, 0, 4, 0.5, 0, 6.5, 3.5, 0, 8, -0.5, 0, 5.5, -3, 0, 3, -1.5, 0, 1, -3.2, 0,
]);

export const scene = defineScene({
  id: 'curves',
  title: 'curves.title',
  text: 'curves.text',
  paper: true,
  params: [
    {
      key: 'scheme',
      label: 'param.scheme',
      type: 'select',
      value: 'four-point',
      refit: false,
      options: () => [
        ['chaikin', 'curves.scheme.chaikin'],
        ['four-point', 'curves.scheme.fourPoint'],
        ['bspline', 'curves.scheme.bspline'],
      ],
    },
    { key: 'steps', label: 'param.steps', type: 'range', min: 0, max: 6, step: 1, value: 4, play: true },
    {
      key: 'w',
      label: 'curves.param.w',
      type: 'range',
      min: -0.05,
      max: 0.2,
      step: 0.001,
      value: 1 / 13,
      exact: true,
      play: true,
      unless: (p) => (p.scheme === 'four-point' ? null : 'curves.reason.w'),
    },
    { key: 'closed', label: 'curves.param.closed', type: 'checkbox', value: false },
    {
      key: 'levels',
      label: 'curves.param.levels',
      type: 'checkbox',
      value: true,
      unless: (p) => (Number(p.steps) < 2 ? 'curves.reason.levels' : null),
    },
  ],
  legend: [
    { style: 'given', label: 'curves.legend.control' },
    { style: 'level', label: 'curves.legend.levels', when: (p) => !!p.levels && Number(p.steps) > 1 },
    { style: 'result', label: 'curves.legend.refined', when: (p) => Number(p.steps) > 0 },
  ],
  create(p, { t, input }) {
    const steps = Number(p.steps),
      closed = !!p.closed;
    // the control polygon: the project's, or the reader's edit of it
    const polygon = input?.points ?? POLYGON;
    const scheme = /** @type {import('../../pkg/ruledlab.js').SubdivideOptions['scheme']} */ (p.scheme);
    /** @returns {import('../../pkg/ruledlab.js').SubdivideOptions} */
    const options = (/** @type {number} */ k) => ({
      scheme,
      steps: k,
      closed,
      ...(scheme === 'four-point' ? { w: Number(p.w) } : scheme === 'bspline' ? { degree: 3 } : {}),
    });
    const levels = [];
    for (let k = p.levels ? 1 : steps; k <= steps; k++) if (k > 0) levels.push(subdividePolygon(polygon, options(k)));
    const final = levels.at(-1) ?? polygon;
    /** @type {import('../scene.js').Layer[]} */
    const layers = [
      { kind: 'polyline', style: 'given', positions: f32(polygon), closed },
      { kind: 'points', style: 'givenPoint', positions: f32(polygon) },
    ];
    for (const level of levels.slice(0, -1))
      layers.push({ kind: 'polyline', style: 'level', positions: f32(level), closed });
    if (steps > 0) {
      layers.push({ kind: 'polyline', style: 'result', positions: f32(final), closed });
      if (steps <= 3) layers.push({ kind: 'points', style: 'resultPoint', positions: f32(final) });
    }
    return {
      bounds: bounds(polygon, final),
      camera: { yaw: -Math.PI / 2, pitch: 1.45 },
      layers,
      readouts: [
        { label: 'curves.readout.points', value: final.length / 3 },
        ...(p.scheme === 'four-point' ? [{ label: 'curves.readout.w', value: Number(p.w) }] : []),
      ],
      description: t('curves.describe', {
        scheme: t(
          p.scheme === 'chaikin'
            ? 'curves.scheme.chaikin'
            : p.scheme === 'bspline'
              ? 'curves.scheme.bspline'
              : 'curves.scheme.fourPoint',
        ),
        steps,
        points: final.length / 3,
      }),
      // the handles: the control points
      input: { sets: [pointSet(Float64Array.from(polygon))], from: t('edit.from.curves') },
    };
  },
});
