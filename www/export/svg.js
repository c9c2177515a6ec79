// The view as a self-contained SVG 1.1 figure (no external CSS or fonts): segments, dots and
// shaded triangles back to front, labels as <text> with subscripts as <tspan>s, an optional
// legend and title; in colour, or in black and white like the paper's figures (grey levels,
// thin and thick, dashed and solid lines instead of colours).
import { figureOf, paint, hex, PAPER } from './figure.js';
import { parseRich } from '../ui/richtext.js';
import { SVG, svgMaker } from '../svg-dom.js';

/**
 * @typedef {object} FigureOptions
 * @property {boolean} [bw]       black and white (default: colour)
 * @property {boolean} [legend]   draw the legend (default true)
 * @property {boolean} [title]    draw the scene's title above the picture (default false)
 * @property {boolean} [labels]   draw the labels (default true)
 */

/**
 * The SVG text of a stage's current view.
 * @param {import('../stage.js').Stage} stage
 * @param {FigureOptions} [options]
 */
export function exportSvg(stage, { bw = false, legend = true, title = false, labels = true } = {}) {
  const fig = figureOf(stage);
  const doc = document.implementation.createDocument(SVG, 'svg', null);
  const svg = doc.documentElement;
  const top = title ? 30 : 0;
  const el = svgMaker(doc);
  const f = (/** @type {number} */ x) => x.toFixed(2);
  for (const [k, v] of Object.entries({
    version: '1.1',
    width: f(fig.width),
    height: f(fig.height + top),
    viewBox: `0 0 ${f(fig.width)} ${f(fig.height + top)}`,
    'font-family': 'Helvetica, Arial, sans-serif',
  }))
    svg.setAttribute(k, v);
  svg.append(
    el('title', {}, fig.title),
    el('rect', { x: 0, y: 0, width: f(fig.width), height: f(fig.height + top), fill: bw ? '#ffffff' : hex(PAPER) }),
  );
  const ink = bw ? '#000000' : '#1d2435';
  const paper = bw ? '#ffffff' : hex(PAPER);
  if (title)
    svg.append(
      el(
        'text',
        { x: 10, y: 20, 'font-size': 15, 'font-weight': 'bold', fill: ink },
        fig.title.replace(/[_^]\{?([^}\s]*)\}?/g, '$1'),
      ),
    );
  const picture = el('g', { transform: `translate(0 ${top})`, 'stroke-linecap': 'round' });
  for (const p of fig.primitives) {
    const look = /** @type {any} */ (paint(p.style, bw));
    if (p.kind === 'segment') {
      const [x1, y1, x2, y2] = p.points;
      const attrs = {
        x1: f(x1),
        y1: f(y1),
        x2: f(x2),
        y2: f(y2),
        stroke: hex(look.color),
        'stroke-width': f(look.width),
      };
      if (look.dash) Object.assign(attrs, { 'stroke-dasharray': look.dash.join(' ') });
      if (look.opacity < 1) Object.assign(attrs, { 'stroke-opacity': look.opacity });
      picture.append(el('line', attrs));
    } else if (p.kind === 'dot') {
      const attrs = {
        cx: f(p.points[0]),
        cy: f(p.points[1]),
        r: f(look.radius),
        fill: look.hollow ? '#ffffff' : hex(look.color),
      };
      if (look.hollow) Object.assign(attrs, { stroke: hex(look.color), 'stroke-width': 0.8 });
      picture.append(el('circle', attrs));
    } else {
      const base = p.back ? look.back : look.color;
      const fill = hex(
        base.map(
          (/** @type {number} */ c) =>
            c * /** @type {number[]} */ (p.fill)[0] + (1 - /** @type {number[]} */ (p.fill)[0]) * 0.08,
        ),
      );
      const attrs = {
        points: [0, 2, 4].map((k) => `${f(p.points[k])},${f(p.points[k + 1])}`).join(' '),
        fill,
        stroke: fill,
        'stroke-width': 0.4,
      };
      if (look.opacity < 1) Object.assign(attrs, { 'fill-opacity': look.opacity, 'stroke-opacity': look.opacity });
      picture.append(el('polygon', attrs));
    }
  }
  svg.append(picture);
  if (labels) {
    const group = el('g', {
      transform: `translate(0 ${top})`,
      'font-family': 'Times New Roman, Times, serif',
      'font-style': 'italic',
      'font-size': 15,
      fill: ink,
    });
    // a paper-coloured halo under every label keeps it legible where a line crosses it (SVG 1.1 has
    // no paint-order, so the halo is a stroked copy drawn first)
    const halo = el('g', {
      stroke: paper,
      'stroke-width': 3,
      'stroke-linejoin': 'round',
      fill: paper,
      'aria-hidden': 'true',
    });
    const text = el('g', {});
    for (const l of fig.labels) {
      halo.append(rich(el, doc, l.text, { x: f(l.x + 3), y: f(l.y + 13) }));
      text.append(rich(el, doc, l.text, { x: f(l.x + 3), y: f(l.y + 13) }));
    }
    group.append(halo, text);
    svg.append(group);
  }
  if (legend && fig.legend.length) {
    const group = el('g', { transform: `translate(10 ${top + 10})`, 'font-size': 12, fill: ink });
    group.append(
      el('rect', {
        x: 0,
        y: 0,
        width: 10 + 36 + 7 * Math.max(...fig.legend.map((e) => e.label.length)),
        height: 8 + 18 * fig.legend.length,
        fill: '#ffffff',
        'fill-opacity': 0.88,
        rx: 5,
      }),
    );
    fig.legend.forEach((entry, k) => {
      const y = 14 + 18 * k;
      const look = /** @type {any} */ (paint(entry.style, bw));
      if ('width' in look) {
        const attrs = {
          x1: 8,
          y1: y,
          x2: 36,
          y2: y,
          stroke: hex(look.color),
          'stroke-width': f(Math.min(Math.max(look.width, 1.2), 5)),
        };
        if (look.dash) Object.assign(attrs, { 'stroke-dasharray': look.dash.join(' ') });
        group.append(el('line', attrs));
      } else if ('radius' in look) {
        group.append(
          el('circle', {
            cx: 22,
            cy: y,
            r: f(Math.min(look.radius, 5)),
            fill: look.hollow ? '#ffffff' : hex(look.color),
            stroke: hex(look.color),
          }),
        );
      } else {
        group.append(
          el('rect', { x: 12, y: y - 6, width: 20, height: 12, fill: hex(look.color), stroke: hex(look.color) }),
        );
      }
      group.append(rich(el, doc, entry.label, { x: 44, y: y + 4 }));
    });
    svg.append(group);
  }
  return `<?xml version="1.0" encoding="UTF-8"?>\n${new XMLSerializer().serializeToString(doc)}\n`;
}

/** A <text> whose R_{i,i+1}-style subscripts are lowered, smaller <tspan>s. */
function rich(
  /** @type {Function} */ el,
  /** @type {XMLDocument} */ doc,
  /** @type {string} */ text,
  /** @type {Record<string, string | number>} */ attrs,
) {
  const node = el('text', attrs);
  let shift = 0;
  for (const part of parseRich(text)) {
    const dy = part.kind === 'sub' ? 4 : part.kind === 'sup' ? -5 : 0;
    const span = el('tspan', { dy: dy - shift, ...(part.kind === 'text' ? {} : { 'font-size': '72%' }) });
    span.append(doc.createTextNode(part.text));
    node.append(span);
    shift = dy;
  }
  return node;
}
