// Section 5, Figs. 11–15: line congruences between two director surfaces, refined by the
// butterfly scheme (16) or variationally; original lines thin, inserted lines thick.
import { AnalyticCongruence } from '../../pkg/ruledlab.js';
import { LineBatch } from '../gl/lines.js';
import { PointBatch } from '../gl/points.js';
import { TriangleMesh, gridIndices } from '../gl/mesh.js';
import { bounds } from '../math.js';
import { COLORS } from '../theme.js';

const SCHEMES = [
  ['butterfly', 'Butterfly (16), all edges'],
  ['diagonal', 'Butterfly, diagonals only (Fig. 13)'],
  ['coupled', 'Variational, coupled'],
  ['two-stage', 'Variational, two-stage (Section 5.2)'],
];

export const scene = {
  id: 'congruence',
  title: 'Line congruences (Figs. 11–15)',
  params: [
    { key: 'congruence', label: 'Congruence', type: 'select', value: 'example5', options: () => AnalyticCongruence.list().map((c) => [c.name, c.title]) },
    { key: 'scheme', label: 'Scheme', type: 'select', value: 'butterfly', options: () => SCHEMES },
    { key: 'steps', label: 'Steps', type: 'range', min: 1, max: 3, step: 1, value: 1 },
    { key: 'director', label: 'Director surface d₁', type: 'checkbox', value: true },
    { key: 'second', label: 'Director surface d₂ (Fig. 11)', type: 'checkbox', value: false },
  ],
  text: `
<h2>Refining a congruence of lines</h2>
<p>A <em>line congruence</em> is a two-parameter family of lines, such as the axis positions of
a milling tool over a surface. Its discrete model is a grid of lines
<math><msub><mi>R</mi><mrow><mi>i</mi><mo>,</mo><mi>j</mi></mrow></msub></math>, each
given by its points <math><msub><mi>p</mi><mrow><mi>i</mi><mo>,</mo><mi>j</mi></mrow></msub></math> and
<math><msub><mi>q</mi><mrow><mi>i</mi><mo>,</mo><mi>j</mi></mrow></msub></math> on two director
surfaces. Refining the congruence means refining both point grids.</p>
<p><strong>Butterfly scheme (Fig. 12).</strong> Triangulate the grid by the diagonals and insert on
each diagonal</p>
<math display="block"><msub><mover><mi>p</mi><mo>‾</mo></mover><mrow><mi>i</mi><mo>,</mo><mi>j</mi></mrow></msub><mo>=</mo><mfrac><mn>1</mn><mn>2</mn></mfrac><mo>(</mo><msub><mi>p</mi><mrow><mi>i</mi><mo>,</mo><mi>j</mi></mrow></msub><mo>+</mo><msub><mi>p</mi><mrow><mi>i</mi><mo>+</mo><mn>1</mn><mo>,</mo><mi>j</mi><mo>+</mo><mn>1</mn></mrow></msub><mo>)</mo><mo>+</mo><mn>2</mn><mi>w</mi><mo>(</mo><mo>…</mo><mo>)</mo><mo>−</mo><mi>w</mi><mo>(</mo><mo>…</mo><mo>)</mo><mspace width="1em"/><mtext>(16)</mtext></math>
<p>The paper inserts only these diagonal lines (Fig. 13); ruledlab also refines the other two
edge directions of the same triangulation, so one step doubles the grid.</p>
<p><strong>Variational subdivision (Fig. 15).</strong> Each row and column of lines is a ruled
surface: the strip scheme inserts lines on the edges, and each face gets the line that makes the
umbrella vector (20) of its eight neighbours vanish, their average. The coupled variant lets all
new lines settle together. Measured against the exact congruence (readout), the butterfly scheme
is the most accurate of all on these examples.</p>`,

  create(p) {
    const ac = AnalyticCongruence.byName(p.congruence);
    const grid = ac.grid();
    const options =
      p.scheme === 'diagonal' ? { scheme: 'butterfly', diagonalOnly: true }
      : p.scheme === 'butterfly' ? { scheme: 'butterfly', steps: p.steps }
      : { scheme: 'variational', variant: p.scheme, K: 6, steps: p.steps };
    const refined = grid.subdivide(options);
    const original = grid.segmentsF32();
    const refinedF64 = refined.segments();
    const shape = { rows: refined.rows, cols: refined.cols };
    const all = refined.segmentsF32();
    // Inserted lines: every line of the diagonal set, or the refined lines not on the old grid.
    const stride = 2 ** p.steps;
    let inserted = all;
    if (p.scheme !== 'diagonal') {
      const keep = [];
      for (let i = 0; i < refined.rows; i++) {
        for (let j = 0; j < refined.cols; j++) if (i % stride || j % stride) keep.push(i * refined.cols + j);
      }
      inserted = new Float32Array(6 * keep.length);
      keep.forEach((k, m) => inserted.set(all.subarray(6 * k, 6 * k + 6), 6 * m));
    }
    const readout = { lines: p.scheme === 'diagonal' ? grid.rows * grid.cols + refined.rows * refined.cols : refined.rows * refined.cols };
    if (p.scheme !== 'diagonal' && p.steps === 1) {
      const e = ac.errors(refined);
      Object.assign(readout, { distanceError: e.distance, angleError: e.angle });
    }
    // director surface d₁ from the densest grid we have
    const dense = p.scheme === 'diagonal' ? grid : refined;
    const d1 = new Float32Array(3 * dense.rows * dense.cols);
    const d2 = new Float32Array(3 * dense.rows * dense.cols);
    const seg = dense === grid ? original : all;
    for (let k = 0; k < dense.rows * dense.cols; k++) {
      d1.set(seg.subarray(6 * k, 6 * k + 3), 3 * k);
      d2.set(seg.subarray(6 * k + 3, 6 * k + 6), 3 * k);
    }
    const indices = gridIndices(dense.rows, dense.cols);
    const feet = new Float32Array(3 * (inserted.length / 6));
    for (let k = 0; k < feet.length / 3; k++) feet.set(inserted.subarray(6 * k, 6 * k + 3), 3 * k);
    for (const o of [grid, refined, ac]) o.free();
    return {
      bounds: bounds(all, original),
      camera: { yaw: -2.1, pitch: 0.85 },
      readout,
      data: { segments: refinedF64, grid: shape },
      readoutLabels: { lines: 'lines shown' },
      build(gl) {
        const layers = [
          new LineBatch(gl, original, { color: COLORS.ruling, width: 1.2 }),
          new LineBatch(gl, inserted, { color: COLORS.striction, width: 2.4 }),
          new PointBatch(gl, feet, { color: COLORS.striction, size: 4 }),
        ];
        if (p.director) layers.push(new TriangleMesh(gl, d1, indices, { front: [0.55, 0.7, 0.88, 0.55], back: [0.96, 0.8, 0.6, 0.55] }));
        if (p.second) layers.push(new TriangleMesh(gl, d2, indices, { front: [0.7, 0.85, 0.7, 0.4], back: [0.85, 0.8, 0.7, 0.4] }));
        return layers;
      },
    };
  },

  legend: [
    ['ruling', 'given lines (thin)'],
    ['striction', 'inserted lines (thick) and their points on d₁'],
  ],
};
