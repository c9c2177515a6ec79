// Section 2, Fig. 1: the notation of a discrete ruled surface on three consecutive rulings of
// the hyperboloid of Example 1 — angles, common perpendiculars, footpoints, distances.
import { AnalyticSurface } from '../../pkg/ruledlab.js';
import { LineBatch } from '../gl/lines.js';
import { PointBatch } from '../gl/points.js';
import { bounds } from '../math.js';
import { COLORS } from '../theme.js';

const sub = (base, index) => `${base}<sub>${index}</sub>`;

export const scene = {
  id: 'notation',
  title: 'Notation: angles, perpendiculars, footpoints (Fig. 1)',
  params: [
    { key: 'spacing', label: 'Ruling spacing H', type: 'range', min: 0.15, max: 0.9, step: 0.01, value: 0.55 },
    { key: 'u', label: 'Parameter u of Rᵢ', type: 'range', min: 0, max: 6.28, step: 0.01, value: 0.7 },
  ],
  text: `
<h2>Fig. 1: the notation</h2>
<p>Three consecutive rulings <i>R</i><sub>i−1</sub>, <i>R</i><sub>i</sub>, <i>R</i><sub>i+1</sub> of the
hyperboloid of Example 1. Each pair has exactly one common perpendicular
<i>N</i><sub>i,i+1</sub> (green); it meets <i>R</i><sub>i</sub> in the footpoint
<i>f</i><sub>i,i+1</sub> and <i>R</i><sub>i+1</sub> in <i>f</i><sub>i+1,i</sub>, at distance
<i>h</i><sub>i,i+1</sub>. The dashed line through <i>f</i><sub>i,i+1</sub> is parallel to
<i>R</i><sub>i+1</sub>: it encloses the angle <i>φ</i><sub>i,i+1</sub> with <i>R</i><sub>i</sub>.
Every ruling carries two footpoints, one from each neighbour; their midpoint (red) is the
discrete striction point. Shrink the spacing and watch the two footpoints close in on it.</p>`,

  create(p) {
    const hyp = AnalyticSurface.byName('hyperboloid');
    const sampled = hyp.sample(3, { uMin: p.u - p.spacing, uMax: p.u + p.spacing, closed: false });
    // short segments centred on the striction points keep the picture on what matters
    const s = sampled.recut(1.6);
    const seg = s.segments();
    const inv = s.invariants();
    for (const o of [hyp, sampled, s]) o.free();
    const f = inv.footpoints; // f_{0,1}, f_{1,0}, f_{1,2}, f_{2,1}
    const point = (k) => [f[3 * k], f[3 * k + 1], f[3 * k + 2]];
    const dir = (i) => {
      const d = [0, 1, 2].map((c) => seg[6 * i + 3 + c] - seg[6 * i + c]);
      const l = Math.hypot(...d);
      return d.map((x) => x / l);
    };
    const fi = point(2); // f_{i,i+1} on the middle ruling
    const e2 = dir(2);
    const parallel = new Float32Array([...fi.map((x, c) => x - 0.9 * e2[c]), ...fi.map((x, c) => x + 0.9 * e2[c])]);
    const mid = [0, 1, 2].map((c) => (f[3 + c] + f[6 + c]) / 2);
    const at = (i, t) => [0, 1, 2].map((c) => seg[6 * i + c] + t * (seg[6 * i + 3 + c] - seg[6 * i + c]));
    const angleAt = fi.map((x, c) => x + 0.35 * (dir(1)[c] + e2[c]));
    return {
      bounds: bounds(seg),
      camera: { yaw: -0.9, pitch: 0.25 },
      readout: { angle: inv.angle[1], distance: inv.distance[1], delta: inv.distribution[1] },
      readoutLabels: { angle: 'angle φ (rad)', distance: 'signed distance h', delta: 'δ = h / φ' },
      labels: [
        { at: at(0, 0.95), html: sub('R', 'i−1') },
        { at: at(1, 0.95), html: sub('R', 'i') },
        { at: at(2, 0.95), html: sub('R', 'i+1') },
        { at: point(2), html: sub('f', 'i,i+1') },
        { at: point(3), html: sub('f', 'i+1,i') },
        { at: point(1), html: sub('f', 'i,i−1') },
        { at: point(2).map((x, c) => 0.3 * x + 0.7 * point(3)[c]), html: `${sub('N', 'i,i+1')}, ${sub('h', 'i,i+1')}` },
        { at: angleAt, html: sub('φ', 'i,i+1') },
        { at: mid, html: sub('m', 'i') },
      ],
      build(gl) {
        return [
          new LineBatch(gl, new Float32Array(seg), { color: COLORS.ruling, width: 2.4 }),
          new LineBatch(gl, new Float32Array(f), { color: COLORS.normal, width: 3 }),
          new LineBatch(gl, parallel, { color: COLORS.ghost, width: 1.6 }),
          new PointBatch(gl, new Float32Array(f), { color: COLORS.foot, size: 9 }),
          new PointBatch(gl, new Float32Array(mid), { color: COLORS.striction, size: 11 }),
        ];
      },
    };
  },

  legend: [
    ['ruling', 'rulings'],
    ['normal', 'common perpendiculars'],
    ['ghost', 'parallel to R<sub>i+1</sub> through f<sub>i,i+1</sub>'],
    ['striction', 'midpoint m<sub>i</sub> of the footpoints on R<sub>i</sub>'],
  ],
};
