// Section 4, Figs. 9–10: variational interpolatory subdivision of a ruled strip (Example 3):
// 12 rulings of the quartic surface, one ruling inserted per pair, both triangulations of the
// refined strip, spheres at the inserted endpoints A_i (light) and B_i (dark).
import { AnalyticSurface, RuledSurface } from '../../pkg/ruledlab.js';
import { LineBatch } from '../gl/lines.js';
import { PointBatch } from '../gl/points.js';
import { stripMesh } from '../gl/mesh.js';
import { bounds } from '../math.js';
import { COLORS } from '../theme.js';

const U = { uMin: -1, uMax: 1, closed: false };

export const scene = {
  id: 'strip',
  title: 'Variational strip subdivision (Figs. 9–10)',
  params: [
    { key: 'scheme', label: 'Scheme', type: 'select', value: 'coupled', options: () => [['coupled', 'Variational, coupled (default)'], ['averaged', 'Variational, averaged umbrella'], ['literal', 'Variational, literal (13)–(15) = midpoint'], ['four-point', 'Four-point w = 1/16 on both boundaries']] },
    { key: 'n', label: 'Parts per segment n', type: 'range', min: 3, max: 24, step: 1, value: 12 },
    { key: 'triangulation', label: 'Triangulation', type: 'select', value: '1', options: () => [['1', 'first (11), "/" diagonals'], ['2', 'second (12), "\\\\" diagonals'], ['none', 'none']] },
    { key: 'exact', label: 'Exact surface (faint)', type: 'checkbox', value: true },
  ],
  text: `
<h2>Variational subdivision of a ruled strip</h2>
<p>Refining the two boundary curves separately ignores the surface between them. The
variational scheme inserts a ruling <math><msub><mi>A</mi><mi>i</mi></msub><msub><mi>B</mi><mi>i</mi></msub></math>
between every pair of rulings, divides all segments into <em>n</em> parts, and triangulates the
refined strip in the two ways of Fig. 9. At a vertex with six neighbours the <em>umbrella
vector</em> (13) is the vertex minus the mean of its neighbours, a discrete mean curvature; the
new endpoints minimise</p>
<math display="block"><mi>F</mi><mo>=</mo><munder><mo>∑</mo><mrow><mi>i</mi><mo>,</mo><mi>k</mi></mrow></munder><mo>(</mo><msubsup><mi>U</mi><mrow><mi>i</mi><mo>,</mo><mi>k</mi></mrow><mn>2</mn></msubsup><mo>+</mo><msubsup><mover><mi>U</mi><mo>~</mo></mover><mrow><mi>i</mi><mo>,</mo><mi>k</mi></mrow><mn>2</mn></msubsup><mo>)</mo><mspace width="1em"/><mtext>(15)</mtext></math>
<p>a quadratic function, so one linear solve. Read literally, with umbrellas at the new points
only, the minimiser is just the midpoint rule (pick "literal"). With umbrellas at every interior
vertex, old ones included, the new rulings couple and follow the surface far better, though the
four-point scheme is better still on this surface: its boundary curves are quadratic, which
w = 1/16 reproduces exactly. The readout measures the distance of the inserted rulings from the
exact surface.</p>`,

  create(p) {
    const quartic = AnalyticSurface.byName('quartic');
    const surface = quartic.sample(12, U);
    const options = p.scheme === 'four-point' ? { scheme: 'four-point' } : { scheme: 'variational', n: p.n, variant: p.scheme };
    const refined = surface.subdivide(options);
    const seg = refined.segments();
    const inserted = new Float64Array(6 * 11);
    for (let i = 0; i < 11; i++) inserted.set(seg.subarray(6 * (2 * i + 1), 6 * (2 * i + 2)), 6 * i);
    const samples = new Float64Array(3 * 11 * 9);
    for (let i = 0; i < 11; i++) {
      for (let k = 0; k <= 8; k++) {
        for (let c = 0; c < 3; c++) samples[3 * (9 * i + k) + c] = inserted[6 * i + c] + (k / 8) * (inserted[6 * i + 3 + c] - inserted[6 * i + c]);
      }
    }
    const distance = quartic.distances(samples, -1.2, 1.2).reduce((a, b) => Math.max(a, b), 0);
    const exact = quartic.sample(120, U);
    const exactSegs = exact.segmentsF32();
    exact.free();
    quartic.free();
    const old = surface.segmentsF32();
    surface.free();
    refined.free();
    const a = new Float32Array(33), b = new Float32Array(33);
    for (let i = 0; i < 11; i++) {
      a.set(inserted.subarray(6 * i, 6 * i + 3), 3 * i);
      b.set(inserted.subarray(6 * i + 3, 6 * i + 6), 3 * i);
    }
    const tri = p.triangulation === 'none' ? null : triangulation(seg, p.n, p.triangulation === '1');
    return {
      bounds: bounds(old),
      camera: { yaw: -2.2, pitch: 0.5 },
      readout: { rulings: seg.length / 6, insertedDistance: distance },
      data: { segments: seg },
      build(gl) {
        const layers = [
          new LineBatch(gl, old, { color: COLORS.ruling, width: 2 }),
          new LineBatch(gl, new Float32Array(inserted), { color: COLORS.striction, width: 3 }),
          new PointBatch(gl, a, { color: COLORS.sphereLight, size: 13 }),
          new PointBatch(gl, b, { color: COLORS.sphereDark, size: 13 }),
        ];
        if (tri) layers.push(new LineBatch(gl, tri, { color: COLORS.mesh, width: 0.8 }));
        if (p.exact) {
          layers.push(stripMesh(gl, exactSegs, { front: [0.7, 0.78, 0.85, 0.28], back: [0.9, 0.85, 0.75, 0.28] }));
        }
        return layers;
      },
    };
  },

  legend: [
    ['ruling', 'given rulings (12 of Example 3)'],
    ['striction', 'inserted rulings'],
    ['sphereLight', 'A<sub>i</sub>'],
    ['sphereDark', 'B<sub>i</sub>'],
    ['mesh', 'triangulation of the refined strip', (p) => p.triangulation !== 'none'],
  ],
};

/**
 * The edges of triangulation 1 ("/" diagonals, neighbours (11)) or 2 ("\" diagonals, (12))
 * of the refined strip: level lines z_{j,k} z_{j+1,k} and one diagonal per quad.
 */
function triangulation(seg, n, first) {
  const cols = seg.length / 6;
  const out = new Float32Array(6 * 2 * (cols - 1) * (n + 1));
  let m = 0;
  const at = (j, k, o) => {
    for (let c = 0; c < 3; c++) out[m++] = seg[6 * j + c] + (k / n) * (seg[6 * j + 3 + c] - seg[6 * j + c]);
  };
  for (let j = 0; j + 1 < cols; j++) {
    for (let k = 0; k <= n; k++) {
      at(j, k);
      at(j + 1, k);
      if (k < n) {
        at(j, first ? k : k + 1);
        at(j + 1, first ? k + 1 : k);
      }
    }
  }
  return out.subarray(0, m);
}
