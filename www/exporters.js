// Exports of what a scene shows: OBJ (strip faces and ruling lines), CSV/JSON of the segments
// (through the core, full precision), JSON of the invariants, PNG of the view, SVG of a
// development. Each returns { filename, content | blob, type }.
import { LineCongruence, RuledSurface } from '../pkg/ruledlab.js';

/** OBJ: the endpoints as vertices, each ruling a line element, consecutive rulings a quad. */
export function obj(segments, { faces = true, name = 'ruledlab' } = {}) {
  const n = segments.length / 6;
  const out = [`# ${name}: ${n} rulings from ruledlab`, `o ${name}`];
  for (let i = 0; i < 2 * n; i++) out.push(`v ${segments[3 * i]} ${segments[3 * i + 1]} ${segments[3 * i + 2]}`);
  for (let i = 0; i < n; i++) out.push(`l ${2 * i + 1} ${2 * i + 2}`);
  if (faces) for (let i = 0; i + 1 < n; i++) out.push(`f ${2 * i + 1} ${2 * i + 2} ${2 * i + 4} ${2 * i + 3}`);
  return out.join('\n') + '\n';
}

/** Runs `use` on a core surface made from `segments`, freeing it afterwards. */
function withSurface(segments, use) {
  const s = RuledSurface.fromSegments(segments instanceof Float64Array ? segments : new Float64Array(segments));
  try {
    return use(s);
  } finally {
    s.free();
  }
}

/** Segment text through the core: a surface, or a congruence when a grid shape is known. */
export function segmentsText(segments, format, grid) {
  const f64 = segments instanceof Float64Array ? segments : new Float64Array(segments);
  const model = grid ? LineCongruence.fromGrid(grid.rows, grid.cols, f64) : RuledSurface.fromSegments(f64);
  try {
    return model.export(format);
  } finally {
    model.free();
  }
}

/** The invariants of Section 2 as JSON (plain arrays; NaN of parallel pairs as null). */
export function invariantsJson(segments) {
  return withSurface(segments, (s) => {
    const inv = s.invariants();
    return JSON.stringify(Object.fromEntries(Object.entries(inv).map(([k, v]) => [k, Array.from(v, (x) => (Number.isFinite(x) ? x : null))])), null, 1);
  });
}

/** The invariants of Section 2 as CSV, one row per pair of consecutive rulings. */
export function invariantsCsv(segments) {
  return withSurface(segments, (s) => {
    const inv = s.invariants();
    const rows = ['pair,angle,distance,distribution,f0x,f0y,f0z,f1x,f1y,f1z,nx,ny,nz,parallel'];
    for (let i = 0; i < inv.angle.length; i++) {
      const f = Array.from(inv.footpoints.subarray(6 * i, 6 * i + 6));
      const n = Array.from(inv.centralNormal.subarray(3 * i, 3 * i + 3));
      rows.push([i, inv.angle[i], inv.distance[i], inv.distribution[i], ...f, ...n, inv.parallel[i]].join(','));
    }
    return rows.join('\n') + '\n';
  });
}

/** A development (x, y of a'_i then b'_i per ruling) as SVG: rulings and the striction image. */
export function developmentSvg(points, strictionPoints = null) {
  const xs = [], ys = [];
  for (let i = 0; i < points.length; i += 2) {
    xs.push(points[i]);
    ys.push(points[i + 1]);
  }
  const [x0, x1, y0, y1] = [Math.min(...xs), Math.max(...xs), Math.min(...ys), Math.max(...ys)];
  const s = 560 / Math.max(x1 - x0, y1 - y0, 1e-9);
  const X = (x) => ((x - x0) * s + 20).toFixed(2);
  const Y = (y) => ((y1 - y) * s + 20).toFixed(2);
  const lines = [];
  for (let i = 0; i + 3 < points.length; i += 4) lines.push(`<line x1="${X(points[i])}" y1="${Y(points[i + 1])}" x2="${X(points[i + 2])}" y2="${Y(points[i + 3])}"/>`);
  const poly = strictionPoints ? `<polyline fill="none" stroke="#d6292b" stroke-width="2" points="${Array.from({ length: strictionPoints.length / 2 }, (_, k) => `${X(strictionPoints[2 * k])},${Y(strictionPoints[2 * k + 1])}`).join(' ')}"/>` : '';
  const w = ((x1 - x0) * s + 40).toFixed(0), h = ((y1 - y0) * s + 40).toFixed(0);
  return `<svg xmlns="http://www.w3.org/2000/svg" width="${w}" height="${h}" viewBox="0 0 ${w} ${h}"><title>Approximate development (ruledlab)</title><g stroke="#21304f" stroke-width="1">${lines.join('')}</g>${poly}</svg>\n`;
}

/** PNG of the canvas: renders, then reads the drawing buffer in the same task. */
export function png(viewer) {
  return new Promise((resolve, reject) => {
    viewer.render();
    viewer.canvas.toBlob((blob) => (blob ? resolve(blob) : reject(new Error('the view could not be captured'))), 'image/png');
  });
}
