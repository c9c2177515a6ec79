// Example 6, Figs. 16–18: a few 5-axis tool positions refined by variational subdivision into
// a smooth tool path; the ball-end tool sweeps a tube whose bottom mills the target profile.
import { ToolPath } from '../../pkg/ruledlab.js';
import { LineBatch } from '../gl/lines.js';
import { PointBatch } from '../gl/points.js';
import { TriangleMesh, gridIndices } from '../gl/mesh.js';
import { bounds } from '../math.js';
import { polylineSegments, tube } from '../geometry.js';
import { COLORS } from '../theme.js';

/** The part surface z = 0.3 sin x cos 0.7y of the example, as a grid. */
function partSurface() {
  const [nx, ny] = [60, 30];
  const pos = new Float32Array(3 * nx * ny);
  for (let i = 0; i < nx; i++) {
    for (let j = 0; j < ny; j++) {
      const x = -0.4 + (6.8 * i) / (nx - 1), y = -2.2 + (4.4 * j) / (ny - 1);
      pos.set([x, y, 0.3 * Math.sin(x) * Math.cos(0.7 * y) - 0.002], 3 * (i * ny + j));
    }
  }
  return { pos, idx: gridIndices(nx, ny) };
}

export const scene = {
  id: 'milling',
  title: '5-axis tool path (Example 6, Figs. 16–18)',
  params: [
    { key: 'poses', label: 'Given poses', type: 'range', min: 4, max: 12, step: 1, value: 7 },
    { key: 'steps', label: 'Steps (Figs. 16–18)', type: 'range', min: 0, max: 3, step: 1, value: 1 },
    { key: 'scheme', label: 'Scheme', type: 'select', value: 'variational', options: () => [['variational', 'Variational (coupled)'], ['averaged', 'Variational (averaged)'], ['four-point', 'Four-point w = 1/16'], ['linear', 'Linear (midpoints)']] },
    { key: 'envelope', label: 'Swept ball (machined surface)', type: 'checkbox', value: true },
    { key: 'part', label: 'Part surface', type: 'checkbox', value: true },
  ],
  text: `
<h2>Example 6: a smooth path for a milling tool</h2>
<p>A few positions of a ball-end tool are given along a profile to be milled (dark). Each is a
segment from the tool tip along the tool axis, so the positions form a discrete ruled surface,
and refining that surface refines the motion (light). After one step (Fig. 16) the path
already follows the profile far better; two and three steps (Figs. 17, 18) make the
orientation change smoothly. The green curve joins the tool's barycentres; the translucent
tube is the envelope of the ball, which leaves the machined surface.</p>
<p>The readout measures what a CAM engineer cares about: how far the machined surface misses
the target profile (its distance from the ball-centre curve minus the radius; positive
leaves material, negative gouges), the largest change of tool orientation between two poses,
and its second difference (how evenly the orientation turns). On this path the variational
scheme beats the four-point scheme on both counts. The buttons export the path as JSON, CSV,
or G-code for a table-table A–C machine (conventions in the file header).</p>`,

  create(p) {
    const path = ToolPath.example(p.poses);
    const options = p.scheme === 'linear' ? { scheme: 'bspline', degree: 1, steps: p.steps }
      : p.scheme === 'four-point' ? { scheme: 'four-point', steps: p.steps }
      : { scheme: 'variational', variant: p.scheme === 'averaged' ? 'averaged' : 'coupled', steps: p.steps };
    const refined = path.refine(options);
    const given = path.segmentsF32();
    const all = refined.segmentsF32();
    const stride = 2 ** p.steps;
    const inserted = new Float32Array(6 * (refined.length - path.length));
    for (let i = 0, m = 0; i < refined.length; i++) if (i % stride) inserted.set(all.subarray(6 * i, 6 * i + 6), 6 * m++);
    const profile = ToolPath.exampleProfile(400);
    const deviation = refined.deviation(profile);
    const quality = refined.quality();
    const centres = refined.cuttingCentres();
    const bary = refined.barycentres();
    const { positions, indices } = tube(centres, 0.25);
    const exports = { json: refined.export('json'), csv: refined.export('csv'), gcode: refined.export('gcode', { scale: 10, feed: 1200 }) };
    path.free();
    refined.free();
    const part = partSurface();
    return {
      bounds: bounds(given, all, profile),
      camera: { yaw: -1.9, pitch: 0.55 },
      readout: {
        poses: quality.angleStep.length + 1,
        deviation: deviation.reduce((m, d) => Math.max(m, Math.abs(d)), 0),
        angleStep: quality.maxAngleStep,
        secondDifference: quality.maxSecondDifference,
      },
      readoutLabels: { poses: 'poses', deviation: 'max |deviation| from the profile', angleStep: 'max orientation step (rad)', secondDifference: 'max 2nd difference of the axis' },
      actions: [
        { label: 'Download JSON', filename: 'toolpath.json', content: exports.json, type: 'application/json' },
        { label: 'Download CSV', filename: 'toolpath.csv', content: exports.csv, type: 'text/csv' },
        { label: 'Download G-code', filename: 'toolpath.nc', content: exports.gcode, type: 'text/plain' },
      ],
      build(gl) {
        const layers = [
          new LineBatch(gl, polylineSegments(profile), { color: COLORS.exact, width: 3 }),
          new LineBatch(gl, given, { color: COLORS.ruling, width: 3 }),
          new LineBatch(gl, inserted, { color: COLORS.insertedAxis, width: 1.6 }),
          new LineBatch(gl, polylineSegments(bary), { color: COLORS.normal, width: 2.4 }),
          new PointBatch(gl, new Float32Array(bary), { color: COLORS.normal, size: 4 }),
        ];
        if (p.envelope) layers.push(new TriangleMesh(gl, positions, indices, { front: [0.85, 0.55, 0.45, 0.35], back: [0.85, 0.55, 0.45, 0.35] }));
        if (p.part) layers.push(new TriangleMesh(gl, part.pos, part.idx, { front: [0.8, 0.8, 0.78, 0.5], back: [0.7, 0.7, 0.7, 0.5] }));
        return layers;
      },
    };
  },

  legend: [
    ['exact', 'target profile'],
    ['ruling', 'given tool axes'],
    ['insertedAxis', 'inserted tool axes'],
    ['normal', 'barycentre curve'],
  ],
};
