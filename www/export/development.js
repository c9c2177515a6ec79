// The development of a ruled strip (Section 2, Fig. 2) as a standalone SVG file, built with
// the DOM and serialised, never from strings.
import { SVG, svgMaker } from '../svg-dom.js';
import { least, greatest } from '../reduce.js';

/**
 * A development (x, y of a'_i then b'_i per ruling), the image of the striction polygon and the
 * polygon the developed rulings envelop (x, y per point) as a standalone SVG file: the rulings
 * thin, the envelope polygon dashed, the striction polygon's image (inscribed in it) thick.
 * @param {ArrayLike<number>} points
 * @param {ArrayLike<number>} striction
 * @param {ArrayLike<number>} envelope
 * @param {string} title
 */
export function developmentSvg(points, striction, envelope, title) {
  const doc = document.implementation.createDocument(SVG, 'svg', null);
  const svg = doc.documentElement;
  const xs = [],
    ys = [];
  for (let i = 0; i + 1 < points.length; i += 2) {
    xs.push(points[i]);
    ys.push(points[i + 1]);
  }
  const [x0, x1, y0, y1] = [least(xs), greatest(xs), least(ys), greatest(ys)];
  const s = 560 / Math.max(x1 - x0, y1 - y0, 1e-9);
  const X = (/** @type {number} */ x) => ((x - x0) * s + 20).toFixed(2);
  const Y = (/** @type {number} */ y) => ((y1 - y) * s + 20).toFixed(2);
  const w = ((x1 - x0) * s + 40).toFixed(0),
    h = ((y1 - y0) * s + 40).toFixed(0);
  for (const [k, v] of Object.entries({ version: '1.1', width: w, height: h, viewBox: `0 0 ${w} ${h}` }))
    svg.setAttribute(k, v);
  const el = svgMaker(doc);
  const titleEl = el('title', {}, title);
  const rulings = el('g', { stroke: '#1f2430', 'stroke-width': '1', fill: 'none' });
  for (let i = 0; i + 3 < points.length; i += 4)
    rulings.append(el('line', { x1: X(points[i]), y1: Y(points[i + 1]), x2: X(points[i + 2]), y2: Y(points[i + 3]) }));
  const polyline = (/** @type {ArrayLike<number>} */ p) =>
    Array.from({ length: Math.floor(p.length / 2) }, (_, k) => `${X(p[2 * k])},${Y(p[2 * k + 1])}`).join(' ');
  svg.append(
    titleEl,
    rulings,
    el('polyline', {
      fill: 'none',
      stroke: '#771100',
      'stroke-width': '1.2',
      'stroke-dasharray': '6 3',
      points: polyline(envelope),
    }),
    el('polyline', { fill: 'none', stroke: '#d55e00', 'stroke-width': '2', points: polyline(striction) }),
  );
  return `${new XMLSerializer().serializeToString(doc)}\n`;
}
