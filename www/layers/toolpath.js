// The milling scene's link to a real machine (Example 6 beyond the paper): the tool path shown —
// the example or your own imported tool poses, for the job's tool —, the controls of the G-code
// post (machine, dialect, mode), the program with what the post did, and the figure beside the
// view: the deviation along the path (the machined surface from the target, against the
// tolerance; the controller's interpolation per block) over the machine's axes along the path
// (the rotary axes' values and speeds, the blocks the axes slowed). The core computes every
// number; this module only asks for them and draws the plots with the DOM.
import { cam } from '../cam.js';
import { stackedPlots } from '../diagrams/plot.js';
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
export function deviationDiagram({ target, scale, stride, post, t, lang = 'en' }) {
  const units = post?.units ?? 'mm';
  /** @type {import('../diagrams/plot.js').Series[]} */
  const deviation = [];
  if (target)
    deviation.push({
      name: t('milling.plot.surface'),
      x: Array.from(target.at, (a) => a / stride),
      y: Array.from(target.points, (d) => d * scale),
    });
  /** @type {import('../diagrams/plot.js').Series[]} */
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
