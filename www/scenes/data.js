// Your data: rulings (or a congruence) pasted or uploaded as CSV or JSON, with its invariants.
import { LineCongruence, RuledSurface } from '../../pkg/ruledlab.js';
import { LineBatch } from '../gl/lines.js';
import { PointBatch } from '../gl/points.js';
import { stripMesh } from '../gl/mesh.js';
import { bounds } from '../math.js';
import { dropNonFinite, polylineSegments } from '../geometry.js';
import { COLORS } from '../theme.js';

/** The current import: { segments: Float64Array, rows?, cols? } (starts with a small example). */
export const imported = { segments: new Float64Array([0, 0, 0, 1, 0, 0, 0, 0, 0.5, 0.7, 0.7, 0.5, 0, 0, 1, 0, 1, 1, 0, 0, 1.5, -0.7, 0.7, 1.5, 0, 0, 2, -1, 0, 2]) };

export const scene = {
  id: 'data',
  title: 'Your data (import CSV or JSON)',
  params: [{ key: 'strip', label: 'Surface strip', type: 'checkbox', value: true }],
  text: `
<h2>Your own rulings</h2>
<p>Paste or upload a CSV file with six numbers per line (a.x a.y a.z b.x b.y b.z, a header line
is fine) or JSON: <code>[[ax, ay, az, bx, by, bz], …]</code>, or
<code>{"rows": r, "cols": c, "segments": […]}</code> for a congruence. Malformed files are
rejected with the line and column of the problem. A ruled surface is shown with its striction
polygon and common perpendiculars; the export buttons save it again, or its invariants.</p>`,

  /** `source` defaults to the page's import; a <ruled-view> passes its own `data`. */
  create(p, source = imported) {
    const { segments, rows, cols } = source;
    if (rows && cols) {
      const c = LineCongruence.fromGrid(rows, cols, segments);
      const seg = c.segmentsF32();
      c.free();
      return {
        bounds: bounds(seg),
        readout: { lines: rows * cols },
        readoutLabels: { lines: `lines (${rows} × ${cols} congruence)` },
        data: { segments, grid: { rows, cols } },
        build: (gl) => [new LineBatch(gl, seg, { color: COLORS.ruling, width: 1.6 })],
      };
    }
    const s = RuledSurface.fromSegments(segments);
    const seg = s.segmentsF32();
    const inv = s.invariants();
    s.free();
    return {
      bounds: bounds(seg),
      readout: { rulings: seg.length / 6, parallelPairs: inv.parallel.reduce((a, b) => a + b, 0) },
      data: { segments },
      build(gl) {
        const layers = [
          new LineBatch(gl, seg, { color: COLORS.ruling, width: 2 }),
          new LineBatch(gl, dropNonFinite(inv.footpoints, 6), { color: COLORS.normal, width: 2.4 }),
          new LineBatch(gl, polylineSegments(inv.striction), { color: COLORS.striction, width: 3 }),
          new PointBatch(gl, dropNonFinite(inv.striction, 3), { color: COLORS.striction, size: 7 }),
        ];
        if (p.strip) layers.push(stripMesh(gl, seg, COLORS.strip));
        return layers;
      },
    };
  },

  legend: [
    ['ruling', 'your rulings'],
    ['normal', 'common perpendiculars'],
    ['striction', 'striction polygon'],
  ],
};
