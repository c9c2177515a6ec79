// Fig. 12, the butterfly scheme, as a picture: the triangulated grid of points p_{i,j} on d₁,
// the diagonal p_{i,j} p_{i+1,j+1} that (16) splits, the new point p̄_{i,j} and the eight stencil
// points with their weights, and formula (16) written out in full. Self-contained SVG 1.1 built
// with the DOM (like the convergence plot), so it is shown beside the view and saved as a file.
// Weights differ by marker shape and label as well as colour.
import { richSvgText, marker, SMALLEST_TEXT } from './plot.js';
import { svgMaker, svgFigure } from '../svg-dom.js';

/** The stencil of (16): grid offsets (di, dj) from p_{i,j} and the weight of each. */
export const BUTTERFLY_STENCIL = /** @type {const} */ ([
  { at: [0, 0], weight: 'half' },
  { at: [1, 1], weight: 'half' },
  { at: [1, 0], weight: 'twoW' },
  { at: [0, 1], weight: 'twoW' },
  { at: [0, -1], weight: 'minusW' },
  { at: [-1, 0], weight: 'minusW' },
  { at: [1, 2], weight: 'minusW' },
  { at: [2, 1], weight: 'minusW' },
]);

/** How each weight is drawn: colour (Okabe–Ito), marker and its label. */
const LOOK = {
  half: { color: '#0072b2', marker: 'square', text: '½' },
  twoW: { color: '#e69f00', marker: 'triangle', text: '2w' },
  minusW: { color: '#cc79a7', marker: 'diamond', text: '−w' },
};

/** The subscript of p at offset (di, dj) from (i, j): "i+1,j−1". */
function index(/** @type {number} */ di, /** @type {number} */ dj) {
  const part = (/** @type {string} */ name, /** @type {number} */ d) =>
    d === 0 ? name : `${name}${d > 0 ? '+' : '−'}${Math.abs(d)}`;
  return `${part('i', di)},${part('j', dj)}`;
}

/**
 * The butterfly stencil of Fig. 12 with formula (16).
 * @param {Document} doc
 * @param {{title: string, weights: string}} spec
 *   title: accessible name; weights: the line under the formula (the weights for the w used)
 * @returns {SVGSVGElement}
 */
export function butterflyStencil(doc, { title, weights }) {
  const el = svgMaker(doc);
  const width = 340,
    height = 372;
  const svg = svgFigure(el, { width, height, title });
  // grid indices i (right) and j (up) from −1 to 2 around p_{i,j}
  const step = 60;
  const px = (/** @type {number} */ di) => 56 + (di + 1) * step;
  const py = (/** @type {number} */ dj) => 215 - (dj + 1) * step;
  const range = [-1, 0, 1, 2];
  const lines = el('g', { stroke: '#b9b5aa', 'stroke-width': 1 });
  for (const a of range) {
    lines.append(
      el('line', { x1: px(-1), y1: py(a), x2: px(2), y2: py(a) }),
      el('line', { x1: px(a), y1: py(-1), x2: px(a), y2: py(2) }),
    );
  }
  // the triangulation by the diagonals p_{i,j} p_{i+1,j+1}
  for (const a of range)
    for (const b of range)
      if (a < 2 && b < 2)
        lines.append(el('line', { x1: px(a), y1: py(b), x2: px(a + 1), y2: py(b + 1), 'stroke-dasharray': '3 3' }));
  svg.append(lines);
  svg.append(el('line', { x1: px(0), y1: py(0), x2: px(1), y2: py(1), stroke: '#1d2435', 'stroke-width': 3 }));
  const dots = el('g', { fill: '#8a8f99' });
  for (const a of range) for (const b of range) dots.append(el('circle', { cx: px(a), cy: py(b), r: 2.5 }));
  svg.append(dots);
  for (const { at, weight } of BUTTERFLY_STENCIL) {
    const look = LOOK[weight];
    const [x, y] = [px(at[0]), py(at[1])];
    const m = marker(el, look.marker, x, y, 6);
    m.setAttribute('fill', look.color);
    m.setAttribute('stroke', '#1d2435');
    svg.append(m);
    svg.append(el('text', { x: x + 9, y: y - 7, 'font-weight': 700, fill: '#1d2435' }, look.text));
    svg.append(
      richSvgText(el, doc, `p_{${index(at[0], at[1])}}`, {
        x: x + 8,
        y: y + 15,
        fill: '#535c70',
        'font-size': SMALLEST_TEXT,
      }),
    );
  }
  // the new point on the diagonal
  const [mx, my] = [(px(0) + px(1)) / 2, (py(0) + py(1)) / 2];
  svg.append(el('circle', { cx: mx, cy: my, r: 6, fill: '#fbfaf7', stroke: '#d55e00', 'stroke-width': 2.5 }));
  svg.append(richSvgText(el, doc, 'p̄_{i,j}', { x: mx - 42, y: my - 6, fill: '#d55e00', 'font-weight': 700 }));
  // formula (16) in full, and the weights for this w
  const f = 268;
  svg.append(richSvgText(el, doc, 'p̄_{i,j} = ½ (p_{i,j} + p_{i+1,j+1})', { x: 12, y: f }));
  svg.append(richSvgText(el, doc, '+ 2w (p_{i+1,j} + p_{i,j+1})', { x: 40, y: f + 20 }));
  svg.append(
    richSvgText(el, doc, '− w (p_{i,j−1} + p_{i−1,j} + p_{i+1,j+2} + p_{i+2,j+1})', {
      x: 40,
      y: f + 40,
      'font-size': 13,
    }),
  );
  svg.append(el('text', { x: width - 12, y: f, 'text-anchor': 'end' }, '(16)'));
  svg.append(el('text', { x: 12, y: f + 66, fill: '#535c70', 'font-size': SMALLEST_TEXT }, weights));
  return svg;
}
