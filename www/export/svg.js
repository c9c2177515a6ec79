// The view as a self-contained SVG 1.1 figure (no external CSS or fonts), drawn like the paper's
// line drawings: surfaces as light flat facets (hatched where black and white must tell two
// apart), then the hidden pieces of lines thin and dashed (or left out), then the visible lines
// and dots over everything — visibility computed by the core (figure.js) — with exact curves on
// a paper-coloured halo; labels as <text> with subscripts as <tspan>s, an optional legend and
// title; in colour, or in black and white (grey levels, widths, dashes and hatching).
import {
  figureOf,
  paint,
  hiddenLook,
  facetColour,
  hatchLines,
  hex,
  HATCH,
  PAPER,
  printFrame,
  PRINT_TYPE,
  labelBox,
  textWidth,
  dashFor,
  runLength,
  LABEL_FONT,
  TEXT_FONT,
} from './projection.js';
import { parseRich, plainRich } from '../ui/richtext.js';
import { SVG, svgMaker } from '../svg-dom.js';
import { HATCH_SPACING, PRINT_WIDTH } from '../limits.js';
import { greatest } from '../reduce.js';

/**
 * @typedef {object} FigureOptions
 * @property {boolean} [bw]       black and white (default: colour)
 * @property {boolean} [legend]   draw the legend (default true)
 * @property {boolean} [title]    draw the scene's title above the picture (default false)
 * @property {boolean} [labels]   draw the labels (default true)
 * @property {'dashed' | 'omit'} [hidden]   hidden parts of lines thin and dashed (default), or left out
 * @property {number} [width]     the printed width in cm (default 8, a column): the figure is
 *   cropped to its drawing and scaled to this width, and line widths, dashes, dots and type keep
 *   their size on paper (a line of the view 1.5 px wide prints 1.1 pt wide at any width)
 */

/**
 * The SVG text of a stage's current view: cropped to the drawing with a small margin, `width`
 * cm wide on paper (its width and height attributes in mm).
 * @param {import('../stage.js').Stage} stage
 * @param {FigureOptions} [options]
 */
export function exportSvg(
  stage,
  { bw = false, legend = true, title = false, labels = true, hidden = 'dashed', width = PRINT_WIDTH.default } = {},
) {
  const fig = figureOf(stage);
  const frame = printFrame(fig, { width, bw, labels, hidden });
  // CSS pixels on paper (0.75 pt) in the figure's pixels
  const nat = frame.nat;
  const doc = document.implementation.createDocument(SVG, 'svg', null);
  const svg = doc.documentElement;
  const plainTitle = plainRich(fig.title);
  // the title in 11 pt, smaller (down to 8 pt) where that is wider than the drawing
  const titleSize = title
    ? Math.max(
        PRINT_TYPE.legend * nat,
        Math.min(
          PRINT_TYPE.title * nat,
          (PRINT_TYPE.title * nat * (frame.w - 2 * nat)) /
            textWidth(plainTitle, PRINT_TYPE.title * nat, TEXT_FONT, 'bold'),
        ),
      )
    : 0;
  const top = title ? 1.8 * titleSize : 0;
  // the legend goes under the picture, where it covers nothing
  const u = (nat * PRINT_TYPE.legend) / 12;
  // each entry's text wrapped within the figure's width (a word wider than that widens it)
  const size = PRINT_TYPE.legend * nat;
  const entries = (legend ? fig.legend : []).map((e) => ({
    ...e,
    lines: wrap(e.label, frame.w - 38 * u - 2 * nat, size),
  }));
  const lineCount = entries.reduce((sum, e) => sum + e.lines.length, 0);
  const below = entries.length ? u * (10 + 18 * entries.length + 15 * (lineCount - entries.length)) : 0;
  const wide = greatest(
    [
      ...entries.flatMap((e) => e.lines.map((line) => u * 38 + textWidth(line, size, TEXT_FONT) + 2 * nat)),
      title ? textWidth(plainTitle, titleSize, TEXT_FONT, 'bold') + 2 * nat : 0,
    ],
    frame.w,
  );
  const [x0, y0, w, h] = [frame.x, frame.y - top, wide, frame.h + top + below];
  const el = svgMaker(doc);
  const f = (/** @type {number} */ x) => x.toFixed(2);
  /** a width, dash or radius (small numbers in a figure of small pixels: three decimals) */
  const w3 = (/** @type {number} */ x) => x.toFixed(3);
  const pts = (/** @type {number[]} */ p) => {
    const out = [];
    for (let k = 0; k + 1 < p.length; k += 2) out.push(`${f(p[k])},${f(p[k + 1])}`);
    return out.join(' ');
  };
  const mm = (/** @type {number} */ x) => `${(x * frame.mm).toFixed(2)}mm`;
  for (const [k, v] of Object.entries({
    version: '1.1',
    width: mm(w),
    height: mm(h),
    viewBox: `${f(x0)} ${f(y0)} ${f(w)} ${f(h)}`,
    'font-family': TEXT_FONT,
  }))
    svg.setAttribute(k, v);
  const paper = bw ? '#ffffff' : hex(PAPER);
  svg.append(el('title', {}, fig.title), el('rect', { x: f(x0), y: f(y0), width: f(w), height: f(h), fill: paper }));
  const ink = bw ? '#000000' : '#1d2435';
  if (title)
    svg.append(
      el(
        'text',
        {
          x: f(frame.x + nat),
          y: f(y0 + 1.2 * titleSize),
          'font-size': f(titleSize),
          'font-weight': 'bold',
          fill: ink,
        },
        plainTitle,
      ),
    );
  const picture = el('g', { 'stroke-linecap': 'round', 'stroke-linejoin': 'round' });
  const hatchPath = (/** @type {number[][]} */ lines) =>
    el('path', {
      d: lines.map((l) => `M${f(l[0])} ${f(l[1])}L${f(l[2])} ${f(l[3])}`).join(''),
      stroke: hex([HATCH.grey, HATCH.grey, HATCH.grey]),
      'stroke-width': w3(HATCH.width * nat),
      fill: 'none',
    });

  // surfaces: light flat facets back to front, each with its hatching in black and white
  const surfaces = el('g', { class: 'surfaces' });
  for (const facet of fig.facets) {
    const look = /** @type {import('./projection.js').AreaLook} */ (paint(facet.style, bw));
    const fill = hex(facetColour(look, facet, bw));
    const attrs = { points: pts(facet.points), fill, stroke: fill, 'stroke-width': w3(0.4 * nat) };
    if (look.opacity < 1) Object.assign(attrs, { 'fill-opacity': look.opacity, 'stroke-opacity': look.opacity });
    surfaces.append(el('polygon', attrs));
    if (look.hatch) {
      const lines = hatchLines(facet.points, look.hatch, HATCH_SPACING * nat);
      if (lines.length) surfaces.append(hatchPath(lines));
    }
  }
  picture.append(surfaces);

  /** A polyline of a run; a dashed run too short for its group's pattern gets a shorter one. */
  const polyline = (/** @type {number[]} */ points, /** @type {number[] | null} */ dash) => {
    const attrs = { points: pts(points) };
    if (dash) {
      const own = dashFor(dash, runLength(points) / nat);
      if (own[0] !== dash[0]) Object.assign(attrs, { 'stroke-dasharray': own.map((d) => w3(d * nat)).join(' ') });
    }
    return el('polyline', attrs);
  };

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
        'stroke-width': w3(look.width * nat),
        'stroke-dasharray': look.dash.map((d) => w3(d * nat)).join(' '),
        ...(look.opacity < 1 ? { 'stroke-opacity': look.opacity } : {}),
      });
      for (const r of runs) g.append(polyline(r.points, look.dash));
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
          r: w3(look.radius * nat),
          fill: look.hollow ? '#ffffff' : hex(look.color),
        };
        if (look.hollow) Object.assign(attrs, { stroke: hex(look.color), 'stroke-width': w3(0.8 * nat) });
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
        'stroke-width': w3((look.width + 3) * nat),
      });
      for (const r of runs) halo.append(el('polyline', { points: pts(r.points) }));
      seen.append(halo);
    }
    const g = el('g', {
      class: `lines set-${k} ${set.style} visible`,
      fill: 'none',
      stroke: hex(look.color),
      'stroke-width': w3(look.width * nat),
      ...(look.dash ? { 'stroke-dasharray': look.dash.map((d) => w3(d * nat)).join(' ') } : {}),
      ...(look.opacity < 1 ? { 'stroke-opacity': look.opacity } : {}),
    });
    for (const r of runs) g.append(polyline(r.points, look.dash));
    seen.append(g);
  });
  picture.append(seen);
  svg.append(picture);

  if (labels) {
    const size = PRINT_TYPE.label * nat;
    const group = el('g', {
      'font-family': LABEL_FONT,
      'font-style': 'italic',
      'font-size': f(size),
      fill: ink,
    });
    // a paper-coloured halo under every label keeps it legible where a line crosses it (SVG 1.1 has
    // no paint-order, so the halo is a stroked copy drawn first)
    const halo = el('g', {
      stroke: paper,
      'stroke-width': f(0.2 * size),
      'stroke-linejoin': 'round',
      fill: paper,
      'aria-hidden': 'true',
    });
    const text = el('g', {});
    for (const l of fig.labels) {
      const at = labelBox(l, size);
      halo.append(rich(el, doc, l.text, { x: f(at.x), y: f(at.baseline) }, size));
      text.append(rich(el, doc, l.text, { x: f(at.x), y: f(at.baseline) }, size));
    }
    group.append(halo, text);
    svg.append(group);
  }
  if (below) svg.append(legendGroup(el, doc, entries, bw, frame.x, frame.y + frame.h, ink, u, nat));
  return `<?xml version="1.0" encoding="UTF-8"?>\n${new XMLSerializer().serializeToString(doc)}\n`;
}

/**
 * The legend from (`x0`, `y0`) down: a sample of each style (at its true width) and its text, laid
 * out in units of `u` (1 at a 12 px type), widths in CSS pixels on paper times `nat`.
 */
function legendGroup(
  /** @type {Function} */ el,
  /** @type {XMLDocument} */ doc,
  /** @type {Array<{style: string, lines: string[]}>} */ entries,
  /** @type {boolean} */ bw,
  /** @type {number} */ x0,
  /** @type {number} */ y0,
  /** @type {string} */ ink,
  /** @type {number} */ u,
  /** @type {number} */ nat,
) {
  const f = (/** @type {number} */ x) => x.toFixed(2);
  const w3 = (/** @type {number} */ x) => x.toFixed(3);
  const group = el('g', {
    class: 'legend',
    transform: `translate(${f(x0)} ${f(y0)})`,
    'font-size': f(12 * u),
    fill: ink,
  });
  let y = 14 * u;
  for (const entry of entries) {
    const look = /** @type {any} */ (paint(entry.style, bw));
    if ('width' in look) {
      const attrs = {
        x1: f(2 * u),
        y1: f(y),
        x2: f(30 * u),
        y2: f(y),
        stroke: hex(look.color),
        'stroke-width': w3(Math.min(Math.max(look.width, 0.6), 6) * nat),
      };
      if (look.dash)
        Object.assign(attrs, { 'stroke-dasharray': look.dash.map((/** @type {number} */ d) => w3(d * nat)).join(' ') });
      group.append(el('line', attrs));
    } else if ('radius' in look) {
      group.append(
        el('circle', {
          cx: f(16 * u),
          cy: f(y),
          r: w3(Math.min(look.radius, 5) * nat),
          fill: look.hollow ? '#ffffff' : hex(look.color),
          stroke: hex(look.color),
          'stroke-width': w3(0.8 * nat),
        }),
      );
    } else {
      const fill = hex(look.color);
      const [x, top, wd, ht] = [6 * u, y - 6 * u, 20 * u, 12 * u];
      group.append(
        el('rect', {
          x: f(x),
          y: f(top),
          width: f(wd),
          height: f(ht),
          fill,
          stroke: hex([0.6, 0.6, 0.6]),
          'stroke-width': w3(0.4 * nat),
        }),
      );
      if (look.hatch) {
        const square = [x, top, x + wd, top, x + wd, top + ht];
        const other = [x, top, x + wd, top + ht, x, top + ht];
        const spacing = HATCH_SPACING * nat;
        const lines = [...hatchLines(square, look.hatch, spacing), ...hatchLines(other, look.hatch, spacing)];
        group.append(
          el('path', {
            d: lines.map((l) => `M${f(l[0])} ${f(l[1])}L${f(l[2])} ${f(l[3])}`).join(''),
            stroke: hex([HATCH.grey, HATCH.grey, HATCH.grey]),
            'stroke-width': w3(HATCH.width * nat),
            fill: 'none',
          }),
        );
      }
    }
    for (const [k, line] of entry.lines.entries())
      group.append(rich(el, doc, line, { x: f(38 * u), y: f(y + (4 + 15 * k) * u) }, 12 * u));
    y += (18 + 15 * (entry.lines.length - 1)) * u;
  }
  return group;
}

/**
 * `text` (with R_{i,i+1}-style scripts) broken into lines at most `width` wide at type `size`,
 * at spaces (never inside a script); a word wider than that stays on a line of its own.
 * @param {string} text @param {number} width @param {number} size
 */
function wrap(text, width, size) {
  const words = text.match(/(?:[^\s{]|\{[^}]*\})+/g) ?? [text];
  /** @type {string[]} */
  const lines = [];
  let line = '';
  for (const word of words) {
    const longer = line ? `${line} ${word}` : word;
    if (line && textWidth(longer, size, TEXT_FONT) > width) {
      lines.push(line);
      line = word;
    } else line = longer;
  }
  return [...lines, line];
}

/** A <text> whose R_{i,i+1}-style subscripts are lowered, smaller <tspan>s (`size`: its type size). */
function rich(
  /** @type {Function} */ el,
  /** @type {XMLDocument} */ doc,
  /** @type {string} */ text,
  /** @type {Record<string, string | number>} */ attrs,
  /** @type {number} */ size,
) {
  // spaces at the ends of a <tspan> ("N_{i,i+1} and") are kept as written
  const node = el('text', { ...attrs, 'xml:space': 'preserve' });
  let shift = 0;
  for (const part of parseRich(text)) {
    const dy = part.kind === 'sub' ? 0.27 * size : part.kind === 'sup' ? -0.33 * size : 0;
    const span = el('tspan', {
      dy: (dy - shift).toFixed(2),
      ...(part.kind === 'text' ? {} : { 'font-size': '72%' }),
    });
    span.append(doc.createTextNode(part.text));
    node.append(span);
    shift = dy;
  }
  return node;
}
