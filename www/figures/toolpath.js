// The milling scene's link to a real machine (Example 6 beyond the paper): the tool path shown —
// the example or your own imported tool poses —, the controls of the G-code post (machine,
// dialect, mode), the program with its linearisation numbers, and the deviation along the path
// as a plot (per pose: how far the ball stands off the target profile; per block: how far the
// controller's interpolation strays from the path). The core computes every number; this
// module only asks for them and draws the plot with the DOM.
import { ToolPath } from '../../pkg/ruledlab.js';
import { svgMaker, svgFigure } from '../svg-dom.js';
import { SMALLEST_TEXT, marker } from '../diagrams/plot.js';
import { PLOT_MARKERS } from '../limits.js';

/** The machines of the post (the core's presets). */
export const MACHINES = /** @type {const} */ (['table-table-ac', 'table-table-bc', 'head-table-bc', 'head-head-ac']);
/** The controllers' languages. */
export const DIALECTS = /** @type {const} */ (['linuxcnc', 'heidenhain', 'sinumerik']);
/** Who does the kinematics. */
export const MODES = /** @type {const} */ (['machine', 'tcp']);

/** The tool of imported poses whose file names none (model units). */
export const IMPORTED_TOOL = { radius: 0.25, length: 1.5, end: /** @type {const} */ ('ball') };

/** Millimetres per model unit in the page's programs (1 unit = 10 mm). */
export const PAGE_SCALE = 10;

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
 * The given path: your imported tool poses (6 numbers per pose: tip, axis) or the example.
 * @param {(o: any) => any} own  the scene's scope (frees the object)
 * @param {import('../scene.js').ImportedData | undefined} data
 * @param {number} poses  the example's number of given poses
 * @returns {{ path: import('../../pkg/ruledlab.js').ToolPath, imported: boolean }}
 */
export function givenPath(own, data, poses) {
  if (data?.poses) return { path: own(ToolPath.fromPoses(data.segments, data.tool ?? IMPORTED_TOOL)), imported: true };
  return { path: own(ToolPath.example(poses)), imported: false };
}

/**
 * The program of the refined path for the machine, dialect and mode chosen, or the error the
 * post gave (a pose beyond the machine's limits is said, not thrown).
 * @param {import('../../pkg/ruledlab.js').ToolPath} refined
 * @param {Record<string, unknown>} p
 * @returns {{ result: import('../../pkg/ruledlab.js').PostResult | null, error: unknown }}
 */
export function postOf(refined, p) {
  try {
    const result = refined.post({
      machine: /** @type {(typeof MACHINES)[number]} */ (p.machine),
      dialect: /** @type {(typeof DIALECTS)[number]} */ (p.dialect),
      mode: /** @type {(typeof MODES)[number]} */ (p.mode),
      scale: PAGE_SCALE,
      feed: 1200,
    });
    return { result, error: null };
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
 * The deviation along the path: series of values over a common x (the position along the given
 * path, pose k at x = k), linear axes, a zero line. Self-contained SVG like the log-log plot.
 * @param {Document} doc
 * @param {{ series: Array<{ name: string, x: ArrayLike<number>, y: ArrayLike<number> }>, xLabel: string, yLabel: string, title: string }} spec
 * @returns {SVGSVGElement}
 */
export function deviationPlot(doc, { series, xLabel, yLabel, title }) {
  const [width, height] = [360, 260];
  const el = svgMaker(doc);
  const svg = svgFigure(el, { width, height, title });
  const pad = { l: 62, r: 12, t: 12, b: 42 };
  const xs = series.flatMap((s) => Array.from(s.x));
  const ys = series.flatMap((s) => Array.from(s.y)).filter(Number.isFinite);
  if (!xs.length || !ys.length) return svg;
  const [x0, x1] = [Math.min(...xs), Math.max(...xs, Math.min(...xs) + 1)];
  let [y0, y1] = [Math.min(0, ...ys), Math.max(0, ...ys)];
  if (y1 - y0 < 1e-12) y1 = y0 + 1e-3;
  const px = (/** @type {number} */ v) => pad.l + ((v - x0) / (x1 - x0)) * (width - pad.l - pad.r);
  const py = (/** @type {number} */ v) => height - pad.b - ((v - y0) / (y1 - y0)) * (height - pad.t - pad.b);
  const grid = el('g', { stroke: '#dedbd2', 'stroke-width': 1 });
  const labels = el('g', { fill: '#333', 'font-size': SMALLEST_TEXT });
  for (let k = 0; k <= 4; k++) {
    const v = y0 + ((y1 - y0) * k) / 4;
    grid.append(el('line', { x1: pad.l, x2: width - pad.r, y1: py(v), y2: py(v) }));
    labels.append(el('text', { x: pad.l - 4, y: py(v) + 4, 'text-anchor': 'end' }, v.toPrecision(2)));
  }
  const xStep = Math.max(1, Math.ceil((x1 - x0) / 6));
  for (let v = Math.ceil(x0); v <= x1; v += xStep) {
    grid.append(el('line', { x1: px(v), x2: px(v), y1: pad.t, y2: height - pad.b }));
    labels.append(el('text', { x: px(v), y: height - pad.b + 17, 'text-anchor': 'middle' }, String(v)));
  }
  svg.append(grid, labels);
  svg.append(el('line', { x1: pad.l, x2: width - pad.r, y1: py(0), y2: py(0), stroke: '#777', 'stroke-width': 1 }));
  series.forEach((s, k) => {
    const look = LOOKS[k % LOOKS.length];
    const pts = Array.from(s.x, (x, i) => [x, s.y[i]]).filter(([, y]) => Number.isFinite(y));
    const g = el('g', { stroke: look.color, fill: look.color });
    g.append(
      el('polyline', {
        fill: 'none',
        'stroke-width': 2,
        'stroke-dasharray': look.dash || 'none',
        points: pts.map(([a, b]) => `${px(a).toFixed(2)},${py(b).toFixed(2)}`).join(' '),
      }),
    );
    if (pts.length <= PLOT_MARKERS) for (const [a, b] of pts) g.append(marker(el, look.marker, px(a), py(b), 2.5));
    svg.append(g);
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
      el('text', { x: pad.l + 31, y: ly, fill: '#222' }, s.name),
    );
    svg.append(key);
  });
  svg.append(el('text', { x: (width + pad.l) / 2, y: height - 6, 'text-anchor': 'middle', fill: '#222' }, xLabel));
  const mid = (height - pad.b) / 2;
  svg.append(
    el('text', { x: 12, y: mid, transform: `rotate(-90 12 ${mid})`, 'text-anchor': 'middle', fill: '#222' }, yLabel),
  );
  return svg;
}

/**
 * The plot of the milling scene: the deviation per pose (the example's ball from its profile, mm)
 * and the linearisation error per block of the program (tip and axis, mm), over the position
 * along the refined path.
 * @param {{ perPose: Float64Array | null, stride: number, post: import('../../pkg/ruledlab.js').PostResult | null, t: (key: string, args?: Record<string, string | number>) => string }} o
 *   stride: refined poses per given pose (the x of refined pose i is i / stride)
 */
export function deviationFigure({ perPose, stride, post, t }) {
  /** @type {Array<{ name: string, x: ArrayLike<number>, y: ArrayLike<number> }>} */
  const series = [];
  if (perPose)
    series.push({
      name: t('milling.plot.pose'),
      x: Array.from(perPose, (_, i) => i / stride),
      y: Array.from(perPose, (d) => d * PAGE_SCALE),
    });
  if (post) {
    // a block's value at its midpoint along the path
    const at = Array.from(post.blockTip, (_, i) => (post.origin[i] + post.origin[i + 1]) / 2 / stride);
    series.push({ name: t('milling.plot.tip'), x: at, y: post.blockTip });
    series.push({ name: t('milling.plot.axis'), x: at, y: post.blockAxis });
  }
  return () =>
    deviationPlot(document, {
      series,
      xLabel: t('milling.plot.x'),
      yLabel: t('milling.plot.y'),
      title: t('milling.plot.title'),
    });
}
