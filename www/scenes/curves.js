// Section 4, Figs. 7–8: Chaikin's corner cutting and the four-point scheme on a polygon,
// step by step, with the tension w of (8) on a slider.
import { subdividePolygon } from '../../pkg/ruledlab.js';
import { LineBatch } from '../gl/lines.js';
import { PointBatch } from '../gl/points.js';
import { bounds } from '../math.js';
import { polylineSegments } from '../geometry.js';
import { COLORS } from '../theme.js';

/** The control polygon: a lopsided star in the plane z = 0, like the paper's figures. */
const POLYGON = new Float64Array([
  0, 0, 0, 2, 3, 0, 4, 0.5, 0, 6.5, 3.5, 0, 8, -0.5, 0, 5.5, -3, 0, 3, -1.5, 0, 1, -3.2, 0,
]);

export const scene = {
  id: 'curves',
  title: 'Curve subdivision (Figs. 7–8)',
  params: [
    { key: 'scheme', label: 'Scheme', type: 'select', value: 'four-point', options: () => [['chaikin', 'Chaikin (Fig. 7)'], ['four-point', 'Four-point, Dyn–Levin–Gregory (Fig. 8)'], ['bspline', 'Cubic B-spline (de Boor)']] },
    { key: 'steps', label: 'Steps', type: 'range', min: 0, max: 6, step: 1, value: 4 },
    { key: 'w', label: 'Tension w (four-point)', type: 'range', min: -0.05, max: 0.2, step: 0.001, value: 0.077 },
    { key: 'closed', label: 'Closed polygon', type: 'checkbox', value: false },
    { key: 'levels', label: 'Show every level', type: 'checkbox', value: true },
  ],
  text: `
<h2>Subdivision of polygons</h2>
<p><strong>Chaikin's algorithm</strong> (Fig. 7) replaces every edge by the points at ¼ and ¾ of its
length. The polygons converge to the quadratic B-spline with the original points as control
points; it touches every edge at its midpoint. The algorithms of de Casteljau and de Boor
work the same way, for Bézier and B-spline curves of any degree.</p>
<p><strong>The four-point scheme</strong> of Dyn, Levin and Gregory (Fig. 8) keeps every point and
inserts a new one on each edge:</p>
<math display="block"><msub><mi>p</mi><mrow><mi>i</mi><mo>+</mo><mfrac><mn>1</mn><mn>2</mn></mfrac></mrow></msub><mo>=</mo><mo>(</mo><mfrac><mn>1</mn><mn>2</mn></mfrac><mo>+</mo><mi>w</mi><mo>)</mo><mo>(</mo><msub><mi>p</mi><mi>i</mi></msub><mo>+</mo><msub><mi>p</mi><mrow><mi>i</mi><mo>+</mo><mn>1</mn></mrow></msub><mo>)</mo><mo>−</mo><mi>w</mi><mo>(</mo><msub><mi>p</mi><mrow><mi>i</mi><mo>−</mo><mn>1</mn></mrow></msub><mo>+</mo><msub><mi>p</mi><mrow><mi>i</mi><mo>+</mo><mn>2</mn></mrow></msub><mo>)</mo><mspace width="1em"/><mtext>(8)</mtext></math>
<p>The limit interpolates the data and is C¹ for 0 &lt; w &lt; ⅛; the paper's figure uses
w = 1/13 ≈ 0.077, and w = 1/16 reproduces cubic polynomials. Slide w to 0 and the limit is the
polygon itself; push it past ⅛ and watch the curve grow kinks. On an open polygon the end
edges use ghost points extrapolated from the last four points.</p>`,

  create(p) {
    const levels = [];
    const options = (steps) => ({ scheme: p.scheme, steps, closed: p.closed, ...(p.scheme === 'four-point' ? { w: p.w } : p.scheme === 'bspline' ? { degree: 3 } : {}) });
    for (let k = p.levels ? 1 : p.steps; k <= p.steps; k++) levels.push(subdividePolygon(POLYGON, options(k)));
    const final = levels.at(-1) ?? POLYGON;
    return {
      bounds: bounds(POLYGON, final),
      camera: { yaw: -Math.PI / 2, pitch: 1.45 },
      readout: { rulings: final.length / 3 },
      readoutLabels: { rulings: 'points' },
      build(gl) {
        const layers = [
          new LineBatch(gl, polylineSegments(POLYGON, p.closed), { color: COLORS.ruling, width: 1.2 }),
          new PointBatch(gl, new Float32Array(POLYGON), { color: COLORS.ruling, size: 9 }),
        ];
        levels.slice(0, -1).forEach((level, i) => {
          const fade = 0.25 + (0.4 * (i + 1)) / levels.length;
          layers.push(new LineBatch(gl, polylineSegments(level, p.closed), { color: [...COLORS.inserted.slice(0, 3), fade], width: 1.2 }));
        });
        if (p.steps > 0) {
          layers.push(new LineBatch(gl, polylineSegments(final, p.closed), { color: COLORS.striction, width: 3 }));
          layers.push(new PointBatch(gl, new Float32Array(final), { color: COLORS.striction, size: p.steps > 3 ? 3 : 6 }));
        }
        return layers;
      },
    };
  },

  legend: [
    ['ruling', 'control polygon'],
    ['inserted', 'intermediate levels', 'levels'],
    ['striction', 'refined polygon'],
  ],
};
