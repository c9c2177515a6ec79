// Beyond the paper: subdivision in the space of lines. Sliding the given endpoints along their
// lines moves the endpoint scheme's surface, but not the line-space scheme's.
import { AnalyticSurface, RuledSurface } from '../../pkg/ruledlab.js';
import { LineBatch } from '../gl/lines.js';
import { stripMesh } from '../gl/mesh.js';
import { bounds } from '../math.js';
import { COLORS } from '../theme.js';

const RANGES = { hyperboloid: { uMin: 0, uMax: 3 }, helical: { uMin: 0, uMax: 6 }, quartic: { uMin: -1, uMax: 1 } };

/** The given segments with both endpoints slid along their lines by `amount` (pattern fixed). */
function slide(seg, amount) {
  const out = seg.slice();
  for (let i = 0; i < seg.length / 6; i++) {
    const [sa, sb] = [Math.sin(2.3 * i + 1), Math.cos(1.7 * i + 0.4)];
    for (let k = 0; k < 3; k++) {
      const d = seg[6 * i + 3 + k] - seg[6 * i + k];
      out[6 * i + k] += amount * 0.6 * sa * d;
      out[6 * i + 3 + k] += amount * 0.6 * sb * d;
    }
  }
  return out;
}

/** Largest angle (radians) between corresponding rulings of two segment arrays. */
function maxAngle(a, b) {
  let worst = 0;
  for (let i = 0; i < a.length; i += 6) {
    const u = [a[i + 3] - a[i], a[i + 4] - a[i + 1], a[i + 5] - a[i + 2]];
    const v = [b[i + 3] - b[i], b[i + 4] - b[i + 1], b[i + 5] - b[i + 2]];
    const c = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
    worst = Math.max(worst, Math.atan2(Math.hypot(...c), Math.abs(u[0] * v[0] + u[1] * v[1] + u[2] * v[2])));
  }
  return worst;
}

export const scene = {
  id: 'lines',
  title: 'Subdivision in line space (beyond the paper)',
  params: [
    { key: 'surface', label: 'Surface', type: 'select', value: 'helical', options: () => [['helical', 'Ruled helical surface'], ['hyperboloid', 'Hyperboloid'], ['quartic', 'Quartic of Example 3']] },
    { key: 'slide', label: 'Slide the given endpoints', type: 'range', min: 0, max: 1, step: 0.01, value: 0.6 },
    { key: 'play', label: 'Animate the slide', type: 'checkbox', value: false, animate: { key: 'slide', period: 3 } },
    { key: 'steps', label: 'Steps', type: 'range', min: 1, max: 3, step: 1, value: 2 },
  ],
  text: `
<h2>Refining the lines, not their endpoints</h2>
<p>Every scheme of Section 4 works on two chosen points per ruling. Slide those points along
their rulings (slider) and the lines do not change — but the refined surface of the
four-point scheme on the endpoints (orange) does: it depends on a choice that is not part of
the geometry.</p>
<p>ruledlab can also refine the lines themselves. An oriented line with direction e through p
is the dual unit vector e + ε (p × e). The four-point rule (8) is applied to these vectors and
each result is pushed back onto the dual unit sphere: a new line. The refined lines (blue) then
depend on the given lines only, and the whole construction commutes with rigid motions; it is
of fourth order, like the endpoint scheme. The readout shows how far the new rulings of each
scheme turned because of the slide.</p>`,

  create(p) {
    const analytic = AnalyticSurface.byName(p.surface);
    const base = analytic.sample(9, { ...RANGES[p.surface], closed: false });
    analytic.free();
    const seg0 = base.segments();
    const slid = RuledSurface.fromSegments(slide(seg0, p.slide));
    const length = seg0.reduce((s, _, i) => (i % 6 ? s : s + Math.hypot(seg0[i + 3] - seg0[i], seg0[i + 4] - seg0[i + 1], seg0[i + 5] - seg0[i + 2])), 0) / 9;
    const options = { scheme: 'four-point', steps: p.steps };
    const ends = slid.subdivide(options);
    const lines = slid.subdivide({ ...options, space: 'lines', length });
    const ends0 = base.subdivide(options).segments();
    const lines0 = base.subdivide({ ...options, space: 'lines', length }).segments();
    const endsSeg = ends.segmentsF32();
    const linesSeg = lines.segmentsF32();
    const linesF64 = lines.segments();
    const readout = { endpointTurn: maxAngle(ends0, ends.segments()), lineTurn: maxAngle(lines0, lines.segments()) };
    const given = slid.segmentsF32();
    for (const o of [base, slid, ends, lines]) o.free();
    return {
      bounds: bounds(seg0, linesSeg),
      camera: { yaw: -1.3, pitch: 0.45 },
      readout,
      data: { segments: linesF64 },
      readoutLabels: { endpointTurn: 'endpoint scheme: new rulings turned by (rad)', lineTurn: 'line-space scheme: turned by (rad)' },
      build(gl) {
        return [
          new LineBatch(gl, given, { color: COLORS.ruling, width: 3 }),
          new LineBatch(gl, endsSeg, { color: [0.9, 0.45, 0.15, 0.8], width: 1.2 }),
          new LineBatch(gl, linesSeg, { color: [0.15, 0.38, 0.75, 1], width: 1.6 }),
          stripMesh(gl, endsSeg, { front: [0.98, 0.6, 0.3, 0.35], back: [0.98, 0.6, 0.3, 0.35] }),
          stripMesh(gl, linesSeg, { front: [0.45, 0.64, 0.9, 0.4], back: [0.45, 0.64, 0.9, 0.4] }),
        ];
      },
    };
  },

  legend: [
    ['ruling', 'given rulings (endpoints slid)'],
    ['endpointScheme', 'four-point on the endpoints'],
    ['lineScheme', 'four-point on the lines'],
  ],
};
