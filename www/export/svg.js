// The view as a self-contained SVG 1.1 figure (no external CSS or fonts), drawn like the paper's
// line drawings: surfaces as light flat facets (hatched where black and white must tell two
// apart), then the hidden pieces of lines thin and dashed (or left out), then the visible lines
// and dots over everything — visibility computed by the core (figure.js) — with exact curves on
// a paper-coloured halo; labels as <text> with subscripts as <tspan>s, an optional legend and
// title; in colour, or in black and white (grey levels, widths, dashes and hatching).
import { figureOf, paint, hiddenLook, facetColour, hatchLines, hex, HATCH, PAPER } from './projection.js';
import { parseRich } from '../ui/richtext.js';
import { SVG, svgMaker } from '../svg-dom.js';

/**
 * @typedef {object} FigureOptions
 * @property {boolean} [bw]       black and white (default: colour)
 * @property {boolean} [legend]   draw the legend (default true)
 * @property {boolean} [title]    draw the scene's title above the picture (default false)
 * @property {boolean} [labels]   draw the labels (default true)
 * @property {'dashed' | 'omit'} [hidden]   hidden parts of lines thin and dashed (default), or left out
 */

/**
 * The SVG text of a stage's current view.
 * @param {import('../stage.js').Stage} stage
 * @param {FigureOptions} [options]
 */
export function exportSvg(stage, { bw = false, legend = true, title = false, labels = true, hidden = 'dashed' } = {}) {
  const fig = figureOf(stage);
  const doc = document.implementation.createDocument(SVG, 'svg', null);
  const svg = doc.documentElement;
  const top = title ? 30 : 0;
  // the legend goes under the picture, where it covers nothing
  const below = legend && fig.legend.length ? 10 + 18 * fig.legend.length : 0;
  const total = fig.height + top + below;
  const el = svgMaker(doc);
  const f = (/** @type {number} */ x) => x.toFixed(2);
  const pts = (/** @type {number[]} */ p) => {
    const out = [];
    for (let k = 0; k + 1 < p.length; k += 2) out.push(`${f(p[k])},${f(p[k + 1])}`);
    return out.join(' ');
  };
  for (const [k, v] of Object.entries({
    version: '1.1',
    width: f(fig.width),
    height: f(total),
    viewBox: `0 0 ${f(fig.width)} ${f(total)}`,
    'font-family': 'Helvetica, Arial, sans-serif',
  }))
    svg.setAttribute(k, v);
  const paper = bw ? '#ffffff' : hex(PAPER);
  svg.append(
    el('title', {}, fig.title),
    el('rect', { x: 0, y: 0, width: f(fig.width), height: f(total), fill: paper }),
  );
  const ink = bw ? '#000000' : '#1d2435';
  if (title)
    svg.append(
      el(
        'text',
        { x: 10, y: 20, 'font-size': 15, 'font-weight': 'bold', fill: ink },
        fig.title.replace(/[_^]\{?([^}\s]*)\}?/g, '$1'),
      ),
    );
  const picture = el('g', { transform: `translate(0 ${top})`, 'stroke-linecap': 'round', 'stroke-linejoin': 'round' });

  // surfaces: light flat facets back to front, each with its hatching in black and white
  const surfaces = el('g', { class: 'surfaces' });
  for (const facet of fig.facets) {
    const look = /** @type {import('./projection.js').AreaLook} */ (paint(facet.style, bw));
    const fill = hex(facetColour(look, facet, bw));
    const attrs = { points: pts(facet.points), fill, stroke: fill, 'stroke-width': 0.4 };
    if (look.opacity < 1) Object.assign(attrs, { 'fill-opacity': look.opacity, 'stroke-opacity': look.opacity });
    surfaces.append(el('polygon', attrs));
    if (look.hatch) {
      const lines = hatchLines(facet.points, look.hatch);
      if (lines.length)
        surfaces.append(
          el('path', {
            d: lines.map((l) => `M${f(l[0])} ${f(l[1])}L${f(l[2])} ${f(l[3])}`).join(''),
            stroke: hex([HATCH.grey, HATCH.grey, HATCH.grey]),
            'stroke-width': HATCH.width,
            fill: 'none',
          }),
        );
    }
  }
  picture.append(surfaces);

  // hidden pieces: thin and dashed, under everything seen
  if (hidden !== 'omit') {
    const behind = el('g', { class: 'hidden' });
    fig.lines.forEach((set, k) => {
      const style = /** @type {any} */ (paint(set.style, bw));
      const runs = set.runs.filter((r) => !r.visible);
      if (!runs.length) return;
      // (a hidden dot is left out: a point behind a surface says nothing its lines do not)
      if (set.kind === 'points') return;
      const look = hiddenLook(style, bw);
      const g = el('g', {
        class: `lines set-${k} ${set.style} hidden`,
        fill: 'none',
        stroke: hex(look.color),
        'stroke-width': f(look.width),
        'stroke-dasharray': look.dash.join(' '),
        ...(look.opacity < 1 ? { 'stroke-opacity': look.opacity } : {}),
      });
      for (const r of runs) g.append(el('polyline', { points: pts(r.points) }));
      behind.append(g);
    });
    picture.append(behind);
  }

  // what is seen, in the scene's order, over every surface
  const seen = el('g', { class: 'visible' });
  fig.lines.forEach((set, k) => {
    const runs = set.runs.filter((r) => r.visible);
    if (!runs.length) return;
    if (set.kind === 'points') {
      const look = /** @type {import('./projection.js').PointLook} */ (paint(set.style, bw));
      const g = el('g', { class: `dots set-${k} ${set.style} visible` });
      for (const r of runs) {
        const attrs = {
          cx: f(r.points[0]),
          cy: f(r.points[1]),
          r: f(look.radius),
          fill: look.hollow ? '#ffffff' : hex(look.color),
        };
        if (look.hollow) Object.assign(attrs, { stroke: hex(look.color), 'stroke-width': 0.8 });
        g.append(el('circle', attrs));
      }
      seen.append(g);
      return;
    }
    const look = /** @type {import('./projection.js').LineLook} */ (paint(set.style, bw));
    if (look.halo) {
      const halo = el('g', {
        class: `halo set-${k} ${set.style}`,
        fill: 'none',
        stroke: paper,
        'stroke-width': f(look.width + 3),
      });
      for (const r of runs) halo.append(el('polyline', { points: pts(r.points) }));
      seen.append(halo);
    }
    const g = el('g', {
      class: `lines set-${k} ${set.style} visible`,
      fill: 'none',
      stroke: hex(look.color),
      'stroke-width': f(look.width),
      ...(look.dash ? { 'stroke-dasharray': look.dash.join(' ') } : {}),
      ...(look.opacity < 1 ? { 'stroke-opacity': look.opacity } : {}),
    });
    for (const r of runs) g.append(el('polyline', { points: pts(r.points) }));
    seen.append(g);
  });
  picture.append(seen);
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
  if (below) svg.append(legendGroup(el, doc, fig.legend, bw, top + fig.height, ink));
  return `<?xml version="1.0" encoding="UTF-8"?>\n${new XMLSerializer().serializeToString(doc)}\n`;
}

/** The legend from `y` down: a sample of each style (at its true width) and its text. */
function legendGroup(
  /** @type {Function} */ el,
  /** @type {XMLDocument} */ doc,
  /** @type {Array<{style: string, label: string}>} */ entries,
  /** @type {boolean} */ bw,
  /** @type {number} */ y0,
  /** @type {string} */ ink,
) {
  const f = (/** @type {number} */ x) => x.toFixed(2);
  const group = el('g', { class: 'legend', transform: `translate(10 ${y0})`, 'font-size': 12, fill: ink });
  entries.forEach((entry, k) => {
    const y = 14 + 18 * k;
    const look = /** @type {any} */ (paint(entry.style, bw));
    if ('width' in look) {
      const attrs = {
        x1: 8,
        y1: y,
        x2: 36,
        y2: y,
        stroke: hex(look.color),
        'stroke-width': f(Math.min(Math.max(look.width, 0.6), 6)),
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
      const fill = hex(look.color);
      group.append(el('rect', { x: 12, y: y - 6, width: 20, height: 12, fill, stroke: hex([0.6, 0.6, 0.6]) }));
      if (look.hatch) {
        const square = [12, y - 6, 32, y - 6, 32, y + 6];
        const other = [12, y - 6, 32, y + 6, 12, y + 6];
        const lines = [...hatchLines(square, look.hatch), ...hatchLines(other, look.hatch)];
        group.append(
          el('path', {
            d: lines.map((l) => `M${f(l[0])} ${f(l[1])}L${f(l[2])} ${f(l[3])}`).join(''),
            stroke: hex([HATCH.grey, HATCH.grey, HATCH.grey]),
            'stroke-width': HATCH.width,
            fill: 'none',
          }),
        );
      }
    }
    group.append(rich(el, doc, entry.label, { x: 44, y: y + 4 }));
  });
  return group;
}

/** A <text> whose R_{i,i+1}-style subscripts are lowered, smaller <tspan>s. */
function rich(
  /** @type {Function} */ el,
  /** @type {XMLDocument} */ doc,
  /** @type {string} */ text,
  /** @type {Record<string, string | number>} */ attrs,
) {
  // spaces at the ends of a <tspan> ("N_{i,i+1} and") are kept as written
  const node = el('text', { ...attrs, 'xml:space': 'preserve' });
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
