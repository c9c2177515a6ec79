// Section 4, Figs. 7–8: Chaikin's corner cutting and the four-point scheme (8) on a polygon,
// step by step, with the tension w on a slider or typed exactly (Fig. 8 uses w = 1/13). The
// core measures the largest turning angle after each step, beyond the steps drawn, and the
// claims say where the four-point scheme's polygons still straighten out on this polygon.
import { subdividePolygon, turningAngles } from '../../pkg/ruledlab.js';
import { defineScene, bounds, f32, schemeParam } from '../scene.js';
import { logLogPlot } from '../diagrams/plot.js';
import { ROUNDING, TURNING_FROM, TURNING_STEPS } from '../limits.js';
import { pointSet } from '../edit/sets.js';

/** The control polygon: eight points in a zigzag in the plane z = 0 (the project's choice; the paper gives no data). */
/** The plane of Figs. 7–8, z = 0 (a point on it, its normal), as a snap target. */
const FIGURE_PLANE = /** @type {import('../scene.js').SnapTargets} */ ({
  kind: 'plane',
  points: new Float64Array([0, 0, 0, 0, 0, 1]),
  name: 'snap.figurePlane',
});

const POLYGON = new Float64Array([
  0, 0, 0, 2, 3, 0, 4, 0.5, 0, 6.5, 3.5, 0, 8, -0.5, 0, 5.5, -3, 0, 3, -1.5, 0, 1, -3.2, 0,
]);

/**
 * The ranges of w the claims state, measured on this polygon (tests/node/claims.test.mjs sweeps
 * them at the slider's step): the largest turning angle falls from TURNING_FROM to TURNING_STEPS
 * steps for 0 < w ≤ falls; from sharp to the slider's end it still exceeds SHARP after
 * TURNING_STEPS steps.
 */
const CLAIMED = {
  closed: { falls: 0.17, sharp: 0.171 },
  open: { falls: 0.126, sharp: 0.127 },
};
/** A turn still this large (rad, about 57°) after TURNING_STEPS steps is a sharp corner. */
const SHARP = 1;

/**
 * The claims of the text about the four-point scheme that apply at w on this polygon.
 * @param {number} w @param {boolean} closed @param {Float64Array} angles   after 0 … TURNING_STEPS steps
 * @returns {import('../scene.js').Claim[]}
 */
function claimsOf(w, closed, angles) {
  const range = closed ? CLAIMED.closed : CLAIMED.open;
  const [before, after] = [angles[TURNING_FROM], angles[TURNING_STEPS]];
  if (w > ROUNDING && w <= range.falls + ROUNDING) return [{ text: 'curves.claim.falls', holds: after < before }];
  if (w >= range.sharp - ROUNDING) return [{ text: 'curves.claim.sharp', holds: after > SHARP }];
  return [];
}

export const scene = defineScene({
  id: 'curves',
  title: 'curves.title',
  text: 'curves.text',
  paper: true,
  params: [
    schemeParam('four-point', () => [
      ['chaikin', 'curves.scheme.chaikin'],
      ['four-point', 'curves.scheme.fourPoint'],
      ['bspline', 'curves.scheme.bspline'],
    ]),
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
  create(p, { t, format, input }) {
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
    // the largest turning angle after 0 … TURNING_STEPS steps (more than are drawn)
    const angles = turningAngles(polygon, options(TURNING_STEPS));
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
    const fourPoint = p.scheme === 'four-point';
    return {
      bounds: bounds(polygon, final),
      camera: { yaw: -Math.PI / 2, pitch: 1.45 },
      layers,
      readouts: [
        { label: 'curves.readout.points', value: final.length / 3 },
        ...(fourPoint ? [{ label: 'curves.readout.w', value: Number(p.w) }] : []),
        { label: 'curves.readout.turning', value: angles[steps] },
        {
          label: 'curves.readout.turningLate',
          value: `${format(angles[TURNING_FROM])} → ${format(angles[TURNING_STEPS])}`,
        },
      ],
      // the claims are about the project's polygon, not an edit of it
      claims: fourPoint && !input ? claimsOf(Number(p.w), closed, angles) : [],
      diagram: () =>
        logLogPlot(document, {
          x: Array.from(angles, (_, k) => k),
          series: [{ name: '', y: Array.from(angles) }],
          linearX: true,
          xLabel: t('curves.plot.x'),
          yLabel: t('curves.plot.y'),
          title: t('curves.plot.title'),
          slopeLabel: () => '',
        }),
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
        angle: angles[steps],
        late: angles[TURNING_STEPS],
        last: TURNING_STEPS,
      }),
      // the handles: the control points, snapping onto each other and onto the plane of the
      // figures (z = 0)
      input: {
        sets: [{ ...pointSet(Float64Array.from(polygon)), targets: [FIGURE_PLANE] }],
        from: t('edit.from.curves'),
      },
    };
  },
});
