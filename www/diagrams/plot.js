// The plots beside the view, built with the DOM as self-contained SVG 1.1 (their own fonts,
// colours, grid and key as presentation attributes: no page CSS needed), so the same element is
// shown on the page and saved as a file: a log-log plot (or, with linearX, x linear and y
// logarithmic) with dashed reference slopes, and linear plots stacked in one figure (the milling
// scene's deviation and axes). Series differ in colour, marker and dash, not in colour alone.

import { parseRich } from '../ui/richtext.js';
import { superscript } from '../i18n/translate.js';
import { svgMaker, svgFigure } from '../svg-dom.js';
import { PLOT_MARKERS } from '../limits.js';
import { least, greatest } from '../reduce.js';

/** The least size of any text in a figure, subscripts included, in user units (= CSS px at 1:1). */
export const SMALLEST_TEXT = 12.5;

const SERIES = [
  { color: '#d55e00', marker: 'circle', dash: '' },
  { color: '#0072b2', marker: 'square', dash: '6 3' },
  { color: '#e69f00', marker: 'triangle', dash: '2 2' },
  { color: '#1f2430', marker: 'diamond', dash: '8 3 2 3' },
  { color: '#56b4e9', marker: 'circle', dash: '1 2' },
];

/**
 * @typedef {object} PlotSpec
 * @property {number[]} x
 * @property {Array<{name: string, y: number[]}>} series   a series named '' gets no key
 * @property {number[]} [slopes]     reference slopes drawn dashed
 * @property {string} xLabel
 * @property {string} yLabel
 * @property {string} title          for the accessible name and the file
 * @property {(order: number) => string} slopeLabel
 * @property {(exponent: number) => string} [tick]   default "10^e"
 * @property {boolean} [linearX]   x on a linear scale with a tick at every integer (steps), y
 *                                 still logarithmic; no reference slopes
 * @property {number} [width]
 * @property {number} [height]
 */

/**
 * @param {Document} doc
 * @param {PlotSpec} spec
 * @returns {SVGSVGElement}
 */
export function logLogPlot(
  doc,
  { x, series, slopes = [], xLabel, yLabel, title, slopeLabel, linearX = false, width = 340, height = 280 },
) {
  const el = svgMaker(doc);
  const svg = svgFigure(el, { width, height, title });
  const pad = { l: 52, r: 12, t: 12, b: 42 };
  const finite = (/** @type {number} */ v) => Number.isFinite(v) && v > 0;
  const ys = series.flatMap((s) => s.y.filter(finite));
  const xs = x.filter(linearX ? Number.isFinite : finite);
  if (!ys.length || !xs.length) return svg;
  const x0 = linearX ? least(xs) : Math.floor(Math.log10(least(xs))),
    x1 = linearX ? greatest(xs) : Math.ceil(Math.log10(greatest(xs)));
  /** Where x lies along the axis, 0 … 1 of [x0, x1] (decades unless linearX). */
  const along = (/** @type {number} */ v) => ((linearX ? v : Math.log10(v)) - x0) / Math.max(x1 - x0, 1);
  const y0 = Math.floor(Math.log10(least(ys))),
    y1 = Math.ceil(Math.log10(greatest(ys)));
  const px = (/** @type {number} */ v) => pad.l + along(v) * (width - pad.l - pad.r);
  const py = (/** @type {number} */ v) =>
    height - pad.b - ((Math.log10(v) - y0) / Math.max(y1 - y0, 1)) * (height - pad.t - pad.b);
  // 10⁻³ in one text with superscript digits: no text smaller than the rest
  const tick = (/** @type {number} */ e) => el('text', { 'font-size': SMALLEST_TEXT }, `10${superscript(e)}`);
  const grid = el('g', { stroke: '#dedbd2', 'stroke-width': 1 });
  const labels = el('g', { fill: '#333' });
  for (let e = x0; e <= x1; e++) {
    const at = linearX ? e : 10 ** e;
    grid.append(el('line', { x1: px(at), x2: px(at), y1: pad.t, y2: height - pad.b }));
    const t = linearX ? el('text', { 'font-size': SMALLEST_TEXT }, String(e)) : tick(e);
    t.setAttribute('x', String(px(at)));
    t.setAttribute('y', String(height - pad.b + 17));
    t.setAttribute('text-anchor', 'middle');
    labels.append(t);
  }
  const every = Math.max(1, Math.ceil((y1 - y0) / 6));
  for (let e = y0; e <= y1; e += every) {
    grid.append(el('line', { x1: pad.l, x2: width - pad.r, y1: py(10 ** e), y2: py(10 ** e) }));
    const t = tick(e);
    t.setAttribute('x', String(pad.l - 4));
    t.setAttribute('y', String(py(10 ** e) + 4));
    t.setAttribute('text-anchor', 'end');
    labels.append(t);
  }
  svg.append(grid, labels);
  // reference slopes through the first point of the first series
  const anchor = series[0].y.findIndex(finite);
  slopes.forEach((p, k) => {
    if (anchor < 0 || linearX) return;
    const xa = x[anchor],
      ya = series[0].y[anchor] * 2;
    const xb = least(xs),
      yb = Math.max(ya * (xb / xa) ** p, 10 ** y0);
    svg.append(
      el('line', {
        x1: px(xa),
        y1: py(ya),
        x2: px(xb),
        y2: py(yb),
        stroke: '#777',
        'stroke-dasharray': '4 3',
        'stroke-width': 1,
      }),
    );
    svg.append(
      el('text', { x: px(xb) + 4, y: py(yb) - 4 - 14 * k, fill: '#555', 'font-size': SMALLEST_TEXT }, slopeLabel(p)),
    );
  });
  series.forEach((s, k) => {
    const look = SERIES[k % SERIES.length];
    const pts = x.map((xv, i) => [xv, s.y[i]]).filter(([xv, yv]) => finite(yv) && xs.includes(xv));
    svg.append(
      seriesMarks(
        el,
        look,
        pts.map(([a, b]) => [px(a), py(b)]),
        { radius: 3 },
      ),
    );
    if (!s.name) return; // a lone series named by the axis needs no key
    const ly = pad.t + 14 + 17 * k;
    const key = el('g', {});
    key.append(
      el('line', {
        x1: pad.l + 8,
        x2: pad.l + 26,
        y1: ly - 4,
        y2: ly - 4,
        stroke: look.color,
        'stroke-width': 2,
        'stroke-dasharray': look.dash || 'none',
      }),
    );
    const m = marker(el, look.marker, pad.l + 17, ly - 4, 3);
    m.setAttribute('fill', look.color);
    key.append(m, richSvgText(el, doc, s.name, { x: pad.l + 31, y: ly, fill: '#222' }));
    svg.append(key);
  });
  svg.append(el('text', { x: (width + pad.l) / 2, y: height - 6, 'text-anchor': 'middle', fill: '#222' }, xLabel));
  svg.append(
    el(
      'text',
      {
        x: 12,
        y: (height - pad.b) / 2,
        transform: `rotate(-90 12 ${(height - pad.b) / 2})`,
        'text-anchor': 'middle',
        fill: '#222',
      },
      yLabel,
    ),
  );
  return svg;
}

/**
 * An SVG <text> of a label with R_{i,i+1}-style subscripts as lowered, smaller <tspan>s.
 * @param {(tag: string, attrs?: Record<string, string | number>, text?: string) => Element} el
 * @param {Document} doc
 * @param {string} label
 * @param {Record<string, string | number>} attrs
 */
export function richSvgText(el, doc, label, attrs) {
  const text = el('text', attrs);
  let shift = 0;
  for (const part of parseRich(label)) {
    const dy = part.kind === 'sub' ? 3 : part.kind === 'sup' ? -4 : 0;
    const span = el('tspan', { dy: dy - shift, ...(part.kind === 'text' ? {} : { 'font-size': SMALLEST_TEXT }) });
    span.append(doc.createTextNode(part.text));
    text.append(span);
    shift = dy;
  }
  return text;
}

/** A marker shape centred at (x, y) (shared with the stencil picture). */
export function marker(
  /** @type {(tag: string, attrs?: Record<string, string | number>) => Element} */ el,
  /** @type {string} */ kind,
  /** @type {number} */ x,
  /** @type {number} */ y,
  /** @type {number} */ r,
) {
  if (kind === 'square') return el('rect', { x: x - r, y: y - r, width: 2 * r, height: 2 * r });
  if (kind === 'triangle')
    return el('polygon', { points: `${x},${y - r * 1.2} ${x - r * 1.1},${y + r * 0.8} ${x + r * 1.1},${y + r * 0.8}` });
  if (kind === 'diamond')
    return el('polygon', { points: `${x},${y - r * 1.3} ${x + r * 1.1},${y} ${x},${y + r * 1.3} ${x - r * 1.1},${y}` });
  return el('circle', { cx: x, cy: y, r });
}

/**
 * A series drawn at its points on screen: its line in its colour and dash (unless `line` is
 * false) and a marker at each of its first `markers` points.
 * @param {ReturnType<typeof svgMaker>} el
 * @param {{ color: string, marker: string, dash: string }} look
 * @param {number[][]} points   [x, y] on screen
 * @param {{ line?: boolean, markers?: number, radius: number }} how
 */
function seriesMarks(el, look, points, { line = true, markers = Number.POSITIVE_INFINITY, radius }) {
  const g = el('g', { stroke: look.color, fill: look.color });
  if (line)
    g.append(
      el('polyline', {
        fill: 'none',
        'stroke-width': 2,
        'stroke-dasharray': look.dash || 'none',
        points: points.map(([a, b]) => `${a.toFixed(2)},${b.toFixed(2)}`).join(' '),
      }),
    );
  for (const [a, b] of points.slice(0, markers)) g.append(marker(el, look.marker, a, b, radius));
  return g;
}

/** The looks of a linear plot's series. */
const LOOKS = [
  { color: '#d55e00', marker: 'circle', dash: '' },
  { color: '#0072b2', marker: 'square', dash: '6 3' },
  { color: '#1f2430', marker: 'triangle', dash: '2 2' },
];

/**
 * @typedef {{ name: string, x: ArrayLike<number>, y: ArrayLike<number>, dots?: boolean }} Series
 *   dots: markers only, no line (blocks that hit a limit)
 * @typedef {{ value: number, name: string }} Level   a horizontal line (the tolerance)
 */

/**
 * Ticks at 1, 2 or 5 times a power of ten covering [lo, hi] with at most 6 intervals: their
 * values (the first at or below lo, the last at or above hi) and the step.
 * @returns {{ values: number[], step: number }}
 */
export function niceTicks(/** @type {number} */ lo, /** @type {number} */ hi) {
  if (!(hi - lo > 1e-12 * Math.max(1, Math.abs(lo), Math.abs(hi)))) hi = lo + Math.max(1e-3, Math.abs(lo) * 1e-3);
  const power = 10 ** Math.floor(Math.log10((hi - lo) / 6));
  const step =
    [1, 2, 5, 10].map((m) => m * power).find((m) => Math.ceil(hi / m) - Math.floor(lo / m) <= 6) ?? 10 * power;
  const first = Math.floor(lo / step);
  const last = Math.ceil(hi / step);
  // (k · step, not a sum of steps: 0.1 + 0.2 would not be 0.3)
  return { values: Array.from({ length: last - first + 1 }, (_, k) => (first + k) * step), step };
}

/** A tick's value with the decimals its step needs, a minus sign and the language's decimal mark. */
export function tickText(/** @type {number} */ v, /** @type {number} */ step, comma = false) {
  const places = Math.max(0, -Math.floor(Math.log10(step) + 1e-9));
  const text = Math.abs(v) < step / 2 ? (0).toFixed(places) : v.toFixed(places);
  return (comma ? text.replace('.', ',') : text).replace('-', '−');
}

/**
 * A plot of series over a common x (the position along the given path, pose k at x = k): linear
 * axes, a zero line, dashed levels. Drawn into `g` of the maker `el`, `width` × `height` at its
 * origin.
 * @param {ReturnType<typeof svgMaker>} el
 * @param {SVGElement} g
 * @param {{ series: Series[], levels?: Level[], xLabel: string, yLabel: string, width: number, height: number, comma?: boolean }} spec
 *   comma: a decimal comma (German)
 */
function drawPlot(el, g, { series, levels = [], xLabel, yLabel, width, height, comma = false }) {
  // the key above the plotting area (a line of it per series, and one for the levels), so that
  // no curve runs under it
  const keyRows = series.length + (levels.length ? 1 : 0);
  const pad = { l: 62, r: 12, t: 12 + 17 * keyRows, b: 42 };
  const xs = series.flatMap((s) => Array.from(s.x));
  const ys = series.flatMap((s) => Array.from(s.y)).filter(Number.isFinite);
  if (!xs.length || !ys.length) return;
  const levelValues = levels.map((l) => l.value).filter(Number.isFinite);
  const [x0, x1] = [least(xs), greatest(xs, least(xs) + 1)];
  const yTicks = niceTicks(least(levelValues, least(ys, 0)), greatest(levelValues, greatest(ys, 0)));
  const [y0, y1] = [yTicks.values[0], yTicks.values[yTicks.values.length - 1]];
  const px = (/** @type {number} */ v) => pad.l + ((v - x0) / (x1 - x0)) * (width - pad.l - pad.r);
  const py = (/** @type {number} */ v) => height - pad.b - ((v - y0) / (y1 - y0)) * (height - pad.t - pad.b);
  const grid = el('g', { stroke: '#dedbd2', 'stroke-width': 1 });
  const labels = el('g', { fill: '#333', 'font-size': SMALLEST_TEXT });
  for (const v of yTicks.values) {
    grid.append(el('line', { x1: pad.l, x2: width - pad.r, y1: py(v), y2: py(v) }));
    labels.append(el('text', { x: pad.l - 4, y: py(v) + 4, 'text-anchor': 'end' }, tickText(v, yTicks.step, comma)));
  }
  const xStep = Math.max(1, Math.ceil((x1 - x0) / 6));
  for (let v = Math.ceil(x0); v <= x1; v += xStep) {
    grid.append(el('line', { x1: px(v), x2: px(v), y1: pad.t, y2: height - pad.b }));
    labels.append(el('text', { x: px(v), y: height - pad.b + 17, 'text-anchor': 'middle' }, String(v)));
  }
  g.append(grid, labels);
  g.append(el('line', { x1: pad.l, x2: width - pad.r, y1: py(0), y2: py(0), stroke: '#777', 'stroke-width': 1 }));
  for (const level of levels) {
    const line = el('line', {
      x1: pad.l,
      x2: width - pad.r,
      y1: py(level.value),
      y2: py(level.value),
      stroke: '#771100',
      'stroke-width': 1.2,
      'stroke-dasharray': '8 4',
    });
    line.append(el('title', {}, level.name));
    g.append(line);
  }
  // the key, above the plotting area
  const keys = el('g', {});
  const keyTop = 4;
  series.forEach((s, k) => {
    const look = LOOKS[k % LOOKS.length];
    const pts = Array.from(s.x, (x, i) => [x, s.y[i]]).filter(([, y]) => Number.isFinite(y));
    g.append(
      seriesMarks(
        el,
        look,
        pts.map(([a, b]) => [px(a), py(b)]),
        { line: !s.dots, markers: s.dots || pts.length <= PLOT_MARKERS ? 4 * PLOT_MARKERS : 0, radius: 2.5 },
      ),
    );
    const ly = keyTop + 14 + 17 * k;
    const swatch = el('g', { stroke: look.color, fill: look.color });
    if (s.dots) swatch.append(marker(el, look.marker, pad.l + 17, ly - 4, 2.5));
    else
      swatch.append(
        el('line', {
          x1: pad.l + 8,
          x2: pad.l + 26,
          y1: ly - 4,
          y2: ly - 4,
          'stroke-width': 2,
          'stroke-dasharray': look.dash || 'none',
        }),
      );
    keys.append(swatch, el('text', { x: pad.l + 31, y: ly, fill: '#222' }, s.name));
  });
  if (levels.length) {
    // the levels (the tolerance's lines) named once in the key
    const ly = keyTop + 14 + 17 * series.length;
    keys.append(
      el('line', {
        x1: pad.l + 8,
        x2: pad.l + 26,
        y1: ly - 4,
        y2: ly - 4,
        stroke: '#771100',
        'stroke-width': 1.2,
        'stroke-dasharray': '8 4',
      }),
      el('text', { x: pad.l + 31, y: ly, fill: '#222' }, levels[0].name),
    );
  }
  if (keyRows) g.append(keys);
  g.append(el('text', { x: (width + pad.l) / 2, y: height - 6, 'text-anchor': 'middle', fill: '#222' }, xLabel));
  const mid = (height - pad.b) / 2;
  g.append(
    el('text', { x: 12, y: mid, transform: `rotate(-90 12 ${mid})`, 'text-anchor': 'middle', fill: '#222' }, yLabel),
  );
}

/**
 * Plots stacked in one self-contained SVG (the first one's title names the figure).
 * @param {Document} doc
 * @param {{ title: string, comma?: boolean, plots: Array<{ series: Series[], levels?: Level[], xLabel: string, yLabel: string, title: string }> }} spec
 * @returns {SVGSVGElement}
 */
export function stackedPlots(doc, { title, plots, comma = false }) {
  const [width, height] = [360, 260];
  const el = svgMaker(doc);
  const svg = svgFigure(el, { width, height: height * Math.max(1, plots.length), title });
  plots.forEach((plot, k) => {
    const g = el('g', { transform: `translate(0 ${k * height})` });
    g.setAttribute('aria-label', plot.title);
    g.append(el('title', {}, plot.title));
    drawPlot(el, g, { ...plot, width, height, comma });
    svg.append(g);
  });
  return svg;
}
