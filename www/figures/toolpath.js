// The milling scene's link to a real machine (Example 6 beyond the paper): the tool path shown —
// the example or your own imported tool poses, for the job's tool —, the controls of the G-code
// post (machine, dialect, mode), the program with what the post did, and the figure beside the
// view: the deviation along the path (the machined surface from the target, against the
// tolerance; the controller's interpolation per block) over the machine's axes along the path
// (the rotary axes' values and speeds, the blocks the axes slowed). The core computes every
// number; this module only asks for them and draws the plots with the DOM.
import { cam } from '../cam.js';
import { svgMaker, svgFigure } from '../svg-dom.js';
import { SMALLEST_TEXT, marker } from '../diagrams/plot.js';
import { PLOT_MARKERS } from '../limits.js';
import { drawnTool, jobOptions } from './job.js';

/** The machines of the post (the core's presets). */
export const MACHINES = /** @type {const} */ (['table-table-ac', 'table-table-bc', 'head-table-bc', 'head-head-ac']);
/** The controllers' languages. */
export const DIALECTS = /** @type {const} */ (['linuxcnc', 'heidenhain', 'sinumerik']);
/** Who does the kinematics. */
export const MODES = /** @type {const} */ (['machine', 'tcp']);

/**
 * The post's controls, added to the milling scene's parameters.
 * @type {import('../scene.js').Param[]}
 */
export const POST_PARAMS = [
  {
    key: 'machine',
    label: 'milling.param.machine',
    type: 'select',
    value: 'table-table-ac',
    refit: false,
    options: () => MACHINES.map((m) => [m, `milling.machine.${m}`]),
  },
  {
    key: 'dialect',
    label: 'milling.param.dialect',
    type: 'select',
    value: 'linuxcnc',
    refit: false,
    options: () => DIALECTS.map((d) => [d, `milling.dialect.${d}`]),
  },
  {
    key: 'mode',
    label: 'milling.param.mode',
    type: 'select',
    value: 'machine',
    refit: false,
    options: () => MODES.map((m) => [m, `milling.mode.${m}`]),
  },
];

/**
 * The given path for the job's tool: your imported tool poses (6 numbers per pose: tip, axis)
 * or the example (its ball touching the profile at every pose).
 * @param {(o: any) => any} own  the scene's scope (frees the object)
 * @param {import('../scene.js').ImportedData | undefined} data
 * @param {Record<string, unknown>} p  the scene's parameters
 * @returns {{ path: import('../../pkg/cam/ruledlab_cam.js').ToolPath, imported: boolean }}
 */
export function givenPath(own, data, p) {
  const tool = drawnTool(p);
  if (data?.poses) return { path: own(cam().ToolPath.fromPoses(data.segments, tool)), imported: true };
  return { path: own(cam().ToolPath.example(Number(p.poses), tool)), imported: false };
}

/**
 * The options of the post for the parameters: the machine, dialect and mode chosen, and the job.
 * @param {Record<string, unknown>} p
 * @param {{ stride: number, lines?: number[] }} [input]
 * @returns {import('../../pkg/cam/ruledlab_cam.js').GcodeOptions}
 */
export function postOptions(p, input) {
  return {
    machine: /** @type {(typeof MACHINES)[number]} */ (p.machine),
    dialect: /** @type {(typeof DIALECTS)[number]} */ (p.dialect),
    mode: /** @type {(typeof MODES)[number]} */ (p.mode),
    ...jobOptions(p, input),
  };
}

/**
 * The program of the refined path for the parameters, or the error the post gave (a pose
 * beyond the machine's limits is said, not thrown).
 * @param {import('../../pkg/cam/ruledlab_cam.js').ToolPath} refined
 * @param {Record<string, unknown>} p
 * @param {{ stride: number, lines?: number[] }} [input]
 * @param {Float64Array | number[] | null} [target]   the part's points the program as posted is measured against
 * @returns {{ result: import('../../pkg/cam/ruledlab_cam.js').PostResult | null, error: unknown }}
 */
export function postOf(refined, p, input, target) {
  try {
    return { result: refined.post({ ...postOptions(p, input), ...(target ? { target } : {}) }), error: null };
  } catch (error) {
    return { result: null, error };
  }
}

/** The file name of a program in a dialect. */
export function programFile(/** @type {string} */ dialect) {
  return dialect === 'heidenhain' ? 'toolpath.h' : dialect === 'sinumerik' ? 'TOOLPATH.MPF' : 'toolpath.ngc';
}

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
  const [x0, x1] = [Math.min(...xs), Math.max(...xs, Math.min(...xs) + 1)];
  const yTicks = niceTicks(Math.min(0, ...ys, ...levelValues), Math.max(0, ...ys, ...levelValues));
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
    const sg = el('g', { stroke: look.color, fill: look.color });
    if (!s.dots)
      sg.append(
        el('polyline', {
          fill: 'none',
          'stroke-width': 2,
          'stroke-dasharray': look.dash || 'none',
          points: pts.map(([a, b]) => `${px(a).toFixed(2)},${py(b).toFixed(2)}`).join(' '),
        }),
      );
    if (s.dots || pts.length <= PLOT_MARKERS)
      for (const [a, b] of pts.slice(0, 4 * PLOT_MARKERS)) sg.append(marker(el, look.marker, px(a), py(b), 2.5));
    g.append(sg);
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

/**
 * The figure of the milling scene: the deviation along the path — the machined surface from
 * the target per target point (job units), with the tolerance's lines, and the linearisation
 * error per block (tip and axis) — and, below it, the machine's rotary axes along the path with
 * the blocks the axes' limits slowed.
 * @param {{
 *   target: { points: Float64Array, at: Float64Array } | null,
 *   scale: number, stride: number,
 *   post: import('../../pkg/cam/ruledlab_cam.js').PostResult | null,
 *   t: (key: string, args?: Record<string, string | number>) => string,
 *   lang?: string,
 * }} o  target: the envelope's deviation (in the poses' units); stride: refined poses per given pose
 */
export function deviationFigure({ target, scale, stride, post, t, lang = 'en' }) {
  const units = post?.units ?? 'mm';
  /** @type {Series[]} */
  const deviation = [];
  if (target)
    deviation.push({
      name: t('milling.plot.surface'),
      x: Array.from(target.at, (a) => a / stride),
      y: Array.from(target.points, (d) => d * scale),
    });
  /** @type {Series[]} */
  const axes = [];
  if (post) {
    // a block's value at its midpoint along the path
    const at = Array.from(post.blockTip, (_, i) => (post.origin[i] + post.origin[i + 1]) / 2 / stride);
    deviation.push({ name: t('milling.plot.tip'), x: at, y: post.blockTip });
    deviation.push({ name: t('milling.plot.axis'), x: at, y: post.blockAxis });
    const poses = Array.from(post.origin, (o) => o / stride);
    for (const k of [0, 1])
      axes.push({
        name: t('milling.plot.rotary', { axis: post.letters[3 + k] }),
        x: poses,
        y: Array.from(poses, (_, i) => post.axes[5 * i + 3 + k]),
      });
    const slowed = Array.from(post.blockLimit, (l, i) => (l ? i : -1)).filter((i) => i >= 0);
    if (slowed.length)
      axes.push({
        name: t('milling.plot.slowed'),
        x: slowed.map((i) => at[i]),
        y: slowed.map((i) => post.axes[5 * (i + 1) + 4]),
        dots: true,
      });
  }
  const tolerance = post?.tolerance ?? 0;
  const levels =
    target && tolerance
      ? [
          { value: tolerance, name: t('milling.plot.tolerance') },
          { value: -tolerance, name: t('milling.plot.tolerance') },
        ]
      : [];
  const title = t('milling.plot.title');
  return () =>
    stackedPlots(document, {
      title,
      comma: lang === 'de',
      plots: [
        { series: deviation, levels, xLabel: t('milling.plot.x'), yLabel: t('milling.plot.y', { units }), title },
        ...(axes.length
          ? [
              {
                series: axes,
                xLabel: t('milling.plot.x'),
                yLabel: t('milling.plot.axesY'),
                title: t('milling.plot.axesTitle'),
              },
            ]
          : []),
      ],
    });
}
