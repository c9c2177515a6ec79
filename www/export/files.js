// Files a scene's data can be saved as: OBJ (strip faces and ruling lines), CSV/JSON of the
// segments (written by the core at full precision), the invariants as JSON or CSV, and the
// development as SVG (built with the DOM and serialised, never from strings).
import { LineCongruence, RuledSurface } from '../../pkg/ruledlab.js';
import { scoped } from '../scene.js';

/** OBJ: the endpoints as vertices, each ruling a line element, consecutive rulings a quad. */
export function obj(/** @type {ArrayLike<number>} */ segments, { faces = true, name = 'ruledlab' } = {}) {
  const n = segments.length / 6;
  const out = [`# ${name}: ${n} rulings from ruledlab`, `o ${name}`];
  for (let i = 0; i < 2 * n; i++) out.push(`v ${segments[3 * i]} ${segments[3 * i + 1]} ${segments[3 * i + 2]}`);
  for (let i = 0; i < n; i++) out.push(`l ${2 * i + 1} ${2 * i + 2}`);
  if (faces) for (let i = 0; i + 1 < n; i++) out.push(`f ${2 * i + 1} ${2 * i + 2} ${2 * i + 4} ${2 * i + 3}`);
  return out.join('\n') + '\n';
}

/** Segment text through the core: a surface, or a congruence when a grid shape is known. */
export function segmentsText(/** @type {Float64Array} */ segments, /** @type {'csv' | 'json'} */ format, /** @type {{rows: number, cols: number} | undefined} */ grid) {
  return scoped((own) => {
    const model = grid ? own(LineCongruence.fromGrid(grid.rows, grid.cols, segments)) : own(RuledSurface.fromSegments(segments));
    return model.export(format);
  });
}

/** The invariants of Section 2 as JSON (plain arrays; the NaN of parallel pairs as null). */
export function invariantsJson(/** @type {Float64Array} */ segments) {
  return scoped((own) => {
    const inv = own(RuledSurface.fromSegments(segments)).invariants();
    return JSON.stringify(Object.fromEntries(Object.entries(inv).map(([k, v]) => [k, Array.from(/** @type {ArrayLike<number>} */ (v), (x) => (Number.isFinite(x) ? x : null))])), null, 1);
  });
}

/** The invariants of Section 2 as CSV, one row per pair of consecutive rulings. */
export function invariantsCsv(/** @type {Float64Array} */ segments) {
  return scoped((own) => {
    const inv = own(RuledSurface.fromSegments(segments)).invariants();
    const rows = ['pair,angle,distance,distribution,f0x,f0y,f0z,f1x,f1y,f1z,nx,ny,nz,parallel'];
    for (let i = 0; i < inv.angle.length; i++) {
      const f = Array.from(inv.footpoints.subarray(6 * i, 6 * i + 6));
      const n = Array.from(inv.centralNormal.subarray(3 * i, 3 * i + 3));
      rows.push([i, inv.angle[i], inv.distance[i], inv.distribution[i], ...f, ...n, inv.parallel[i]].join(','));
    }
    return rows.join('\n') + '\n';
  });
}

const SVG = 'http://www.w3.org/2000/svg';

/**
 * A development (x, y of a'_i then b'_i per ruling) and the image of the striction polygon
 * (x, y per point) as a standalone SVG file.
 * @param {ArrayLike<number>} points
 * @param {ArrayLike<number>} striction
 * @param {string} title
 */
export function developmentSvg(points, striction, title) {
  const doc = document.implementation.createDocument(SVG, 'svg', null);
  const svg = doc.documentElement;
  const xs = [], ys = [];
  for (let i = 0; i + 1 < points.length; i += 2) {
    xs.push(points[i]);
    ys.push(points[i + 1]);
  }
  const [x0, x1, y0, y1] = [Math.min(...xs), Math.max(...xs), Math.min(...ys), Math.max(...ys)];
  const s = 560 / Math.max(x1 - x0, y1 - y0, 1e-9);
  const X = (/** @type {number} */ x) => ((x - x0) * s + 20).toFixed(2);
  const Y = (/** @type {number} */ y) => ((y1 - y) * s + 20).toFixed(2);
  const w = ((x1 - x0) * s + 40).toFixed(0), h = ((y1 - y0) * s + 40).toFixed(0);
  for (const [k, v] of Object.entries({ version: '1.1', width: w, height: h, viewBox: `0 0 ${w} ${h}` })) svg.setAttribute(k, v);
  const el = (/** @type {string} */ tag, /** @type {Record<string, string>} */ attrs) => {
    const e = doc.createElementNS(SVG, tag);
    for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
    return e;
  };
  const titleEl = el('title', {});
  titleEl.textContent = title;
  const rulings = el('g', { stroke: '#1f2430', 'stroke-width': '1', fill: 'none' });
  for (let i = 0; i + 3 < points.length; i += 4) rulings.append(el('line', { x1: X(points[i]), y1: Y(points[i + 1]), x2: X(points[i + 2]), y2: Y(points[i + 3]) }));
  const poly = Array.from({ length: Math.floor(striction.length / 2) }, (_, k) => `${X(striction[2 * k])},${Y(striction[2 * k + 1])}`).join(' ');
  svg.append(titleEl, rulings, el('polyline', { fill: 'none', stroke: '#d55e00', 'stroke-width': '2', points: poly }));
  return new XMLSerializer().serializeToString(doc) + '\n';
}
