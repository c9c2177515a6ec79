// Example 6, Figs. 16–18: a few 5-axis tool poses refined by a strip scheme into a smooth tool
// path; the ball-end tool (drawn at one pose, Fig. 16) sweeps a tube whose lower half is the
// machined surface. The part, the envelope and the tool are meshes built by the core. Beyond the
// paper: the job a machinist posts (layers/job.js) — the program for the machine, controller
// and mode chosen, the machined surface against your target curve, the machine's axes along the
// path —, a long job refined and posted in the worker (post-job.js), and the poses optimised
// against the target in the worker (optimise-job.js), the program's deviation before and after.
import { cam } from '../cam.js';
import { defineScene, scoped, bounds, f32, schemeParam } from '../scene.js';
import { POST_PARAMS, givenPath, postOf, postOptions, programFile, deviationDiagram } from '../layers/toolpath.js';
import { JOB_PARAMS, drawnTool, stockOf } from '../layers/job.js';
import { optimiseInWorker, postInWorker } from '../compute.js';
import { poseSet, poseValues } from '../edit/sets.js';
import { DRAW_LIMIT, POST_WORKER_THRESHOLD, SWEEP_WORKER_WORK } from '../limits.js';

/** @type {Record<string, Partial<import('../../pkg/ruledlab.js').SubdivideOptions>>} */
const SCHEMES = {
  variational: { scheme: 'variational', variant: 'coupled' },
  averaged: { scheme: 'variational', variant: 'averaged' },
  'four-point': { scheme: 'four-point' },
  linear: { scheme: 'bspline', degree: 1 },
};

/**
 * Whether the schemes turn the tool as the text says: the midpoint rule in the smallest largest
 * steps (it halves each turn) but least evenly (the largest second difference), the averaged
 * variational scheme most evenly (the smallest second difference).
 * @param {Record<string, {maxAngleStep: number, maxSecondDifference: number}>} turns   per scheme
 */
function turnsAsSaid(turns) {
  const others = Object.entries(turns).filter(([k]) => k !== 'linear');
  const { linear, averaged } = turns;
  return (
    others.every(
      ([, q]) => linear.maxAngleStep < q.maxAngleStep && linear.maxSecondDifference > q.maxSecondDifference,
    ) && others.every(([k, q]) => k === 'averaged' || averaged.maxSecondDifference < q.maxSecondDifference)
  );
}

/** Largest |deviation| of the machined surface from the target profile. */
function maxDeviation(
  /** @type {import('../../pkg/cam/ruledlab_cam.js').ToolPath} */ path,
  /** @type {Float64Array} */ profile,
) {
  return path.deviation(profile).reduce((m, d) => Math.max(m, Math.abs(d)), 0);
}

/** The largest of an array's absolute values (0 for none). */
const largest = (/** @type {ArrayLike<number>} */ xs) => Array.from(xs).reduce((m, x) => Math.max(m, Math.abs(x)), 0);

/**
 * The post's warnings in the reader's language (the core's reason and values, its line).
 * @param {import('../../pkg/cam/ruledlab_cam.js').PostResult['warnings']} warnings
 * @param {import('../scene.js').Context} ctx
 */
function warningTexts(warnings, { t, format }) {
  return warnings.map((w) => {
    /** @type {Record<string, string>} */
    const args = {};
    for (const [k, v] of Object.entries(w.args ?? {}))
      if (k.endsWith('Reason')) args[k.slice(0, -6)] = t(`error.${v}`);
      else args[k] ??= typeof v === 'number' ? format(v) : String(v);
    const text = t(`error.${w.reason}`, args);
    return w.line ? `${text} ${t('error.atLine', { line: w.line })}` : text;
  });
}

/**
 * The twelve edges of a box as f32 segments (the stock, drawn in the poses' units).
 * @param {[[number, number, number], [number, number, number]]} box
 * @param {number} scale  program units per unit of the poses
 */
function boxEdges([lo, hi], scale) {
  const c = (/** @type {number} */ k) => [k & 1 ? hi[0] : lo[0], k & 2 ? hi[1] : lo[1], k & 4 ? hi[2] : lo[2]];
  const edges = [0, 1, 0, 2, 1, 3, 2, 3, 4, 5, 4, 6, 5, 7, 6, 7, 0, 4, 1, 5, 2, 6, 3, 7];
  return new Float32Array(edges.flatMap((k) => c(k).map((x) => x / scale)));
}

/**
 * The post's readouts: what it inserted, how far the interpolation strayed, the rotary axes'
 * speeds and steps, the blocks the axes slowed, the unwinds, the pole cone, the time.
 * @param {import('../../pkg/cam/ruledlab_cam.js').PostResult} post
 * @param {(x: number) => string} format   numbers in the page's language
 */
function postReadouts(post, format) {
  const u = post.units;
  const letters = post.letters.slice(3);
  const speeds = letters.map(
    (l, k) => `${l} ${format(Math.round(largest(post.blockRotarySpeed.filter((_, i) => i % 2 === k))))}`,
  );
  const steps = letters.map((l, k) => {
    let m = 0;
    for (let i = 5 + 3 + k; i < post.axes.length; i += 5) m = Math.max(m, Math.abs(post.axes[i] - post.axes[i - 5]));
    return `${l} ${format(m)}`;
  });
  const d = post.deviation;
  return [
    // the target's deviation from the sweep of the program as posted
    ...(d
      ? [
          { label: `milling.readout.posted.${u}`, value: Math.abs(d.largest) },
          { label: `milling.readout.gouge.${u}`, value: -d.gouge },
          { label: `milling.readout.leave.${u}`, value: d.leave },
          { label: `milling.readout.rms.${u}`, value: d.rms },
          {
            label: 'milling.readout.beyond',
            value: Array.from(d.points).filter((x) => Math.abs(x) > post.tolerance).length,
          },
        ]
      : []),
    { label: 'milling.readout.inserted', value: post.inserted },
    { label: `milling.readout.linearTip.${u}`, value: post.before.tip },
    { label: `milling.readout.linearAxis.${u}`, value: post.before.axis },
    { label: 'milling.readout.rotarySpeed', value: speeds.join(', ') },
    { label: 'milling.readout.rotaryStep', value: steps.join(', ') },
    { label: 'milling.readout.slowed', value: Array.from(post.blockLimit).filter(Boolean).length },
    { label: 'milling.readout.unwinds', value: post.unwinds.length },
    { label: 'milling.readout.cone', value: Array.from(post.adjusted).filter((a) => a > 0).length },
    { label: 'milling.readout.minutes', value: post.blockMinutes.reduce((s, m) => s + m, 0) },
  ];
}

export const scene = defineScene({
  id: 'milling',
  title: 'milling.title',
  text: 'milling.text',
  paper: true,
  // tool paths and their G-code are the CAM module's
  needs: ['cam'],
  // an edit of the poses replaces the example's
  fixed: ['poses'],
  params: [
    { key: 'poses', label: 'milling.param.poses', type: 'range', min: 4, max: 12, step: 1, value: 7 },
    { key: 'steps', label: 'milling.param.steps', type: 'range', min: 0, max: 3, step: 1, value: 1, play: true },
    schemeParam('variational', () => Object.keys(SCHEMES).map((s) => [s, `milling.scheme.${s}`]), {
      unless: (p) => (Number(p.steps) === 0 ? 'milling.reason.steps' : null),
    }),
    { key: 'tool', label: 'milling.param.tool', type: 'checkbox', value: true },
    {
      key: 'at',
      label: 'milling.param.at',
      type: 'range',
      min: 0,
      max: 1,
      step: 0.01,
      value: 0.35,
      play: true,
      unless: (p) => (p.tool ? null : 'milling.reason.tool'),
    },
    { key: 'envelope', label: 'milling.param.envelope', type: 'checkbox', value: true },
    { key: 'part', label: 'milling.param.part', type: 'checkbox', value: true },
    { key: 'optimise', label: 'milling.param.optimise', type: 'checkbox', value: false },
    ...POST_PARAMS,
    ...JOB_PARAMS,
  ],
  legend: [
    { style: 'exact', label: 'milling.legend.profile' },
    { style: 'given', label: 'milling.legend.given' },
    { style: 'insertedAxis', label: 'milling.legend.inserted', when: (p) => Number(p.steps) > 0 },
    { style: 'barycentre', label: 'milling.legend.barycentre' },
    { style: 'envelope', label: 'milling.legend.envelope', when: (p) => !!p.envelope },
    { style: 'tool', label: 'milling.legend.tool', when: (p) => !!p.tool },
    { style: 'part', label: 'milling.legend.part', when: (p) => !!p.part },
    { style: 'optimisedAxis', label: 'milling.legend.optimised', when: (p) => !!p.optimise },
  ],
  create(p, ctx) {
    const { t, data, input } = ctx;
    return scoped((own) => {
      const steps = Number(p.steps);
      const scale = Number(p.scale);
      // your imported tool poses, or the example of Figs. 16–18 (its profile and part with it)
      const { path: base, imported } = givenPath(own, data, p);
      // the given poses as the reader moved them (the same tool)
      const edited = input?.poses;
      const path = edited ? own(cam().ToolPath.fromSegments(edited, base.tool)) : base;
      // the input's numbering: errors and warnings name your pose and its line
      const numbering = { stride: 2 ** steps, ...(imported && !edited && data?.lines ? { lines: data.lines } : {}) };
      const expected = (path.length - 1) * 2 ** steps + 1;
      if (expected > POST_WORKER_THRESHOLD) return largeJob(path, p, ctx, numbering);
      const refined = own(path.refine({ ...SCHEMES[/** @type {keyof typeof SCHEMES} */ (p.scheme)], steps }));
      // the given axes as the poses were given: an edited axis point stays where the reader put
      // it (the tool keeps its length along that direction)
      const given = edited ? f32(edited) : path.segmentsF32();
      const all = refined.segmentsF32();
      const profile = imported ? null : cam().ToolPath.exampleProfile(400);
      // the target the machined surface is measured against: the example's profile, or yours
      const target = profile ?? data?.target ?? null;
      // many poses against many target points: the post and its program's deviation are made in
      // the worker, with progress (the picture comes first)
      const inWorker = !!target && refined.length * (target.length / 3) > SWEEP_WORKER_WORK;
      const surface = target && !inWorker ? refined.envelopeDeviation(target) : null;
      const deviation = profile ? maxDeviation(refined, profile) : Number.NaN;
      const quality = refined.quality();
      // every scheme's deviation and orientation at these steps, for the comparisons the text
      // makes (and their claims)
      /** @type {Record<string, number>} */
      const compare = {};
      /** @type {Record<string, {maxAngleStep: number, maxSecondDifference: number}>} */
      const turns = {};
      if (profile)
        for (const [k, o] of Object.entries(SCHEMES)) {
          const other = own(path.refine({ ...o, steps }));
          compare[k] = maxDeviation(other, profile);
          turns[k] = other.quality();
        }
      const given0 = profile ? maxDeviation(path, profile) : Number.NaN;
      const centres = refined.barycentres();
      const perPose = profile ? refined.deviationPerPose(profile) : null;
      /** @type {import('../scene.js').Layer[]} */
      const layers = [
        ...(target
          ? [/** @type {import('../scene.js').Layer} */ ({ kind: 'polyline', style: 'exact', positions: f32(target) })]
          : []),
        { kind: 'segments', style: 'given', positions: given },
        { kind: 'polyline', style: 'barycentre', positions: f32(centres) },
        { kind: 'points', style: 'barycentrePoint', positions: f32(centres) },
      ];
      if (steps > 0)
        layers.push({ kind: 'segments', style: 'insertedAxis', positions: refined.insertedF32(2 ** steps) });
      if (p.envelope) {
        const { positions, indices } = refined.envelopeMesh(14);
        layers.push({ kind: 'mesh', style: 'envelope', positions, indices });
      }
      if (p.tool) {
        const { positions, indices } = refined.toolMesh(Math.round(Number(p.at) * (refined.length - 1)), 20);
        layers.push({ kind: 'mesh', style: 'tool', positions, indices });
      }
      if (p.part && !imported) {
        const { positions, indices } = cam().ToolPath.examplePart(60, 30);
        layers.push({ kind: 'mesh', style: 'part', positions, indices });
      }
      // the G-code post for the machine, controller, mode and job chosen (measured against the
      // target: the deviation of the program as posted), here or in the worker
      const { result: post, error: postError } = inWorker
        ? { result: null, error: null }
        : postOf(refined, p, numbering, target);
      // what the worker needs of the path, read now: the scope frees it when create() returns
      const poses = inWorker || (p.optimise && target) ? interleave(refined.tips(), refined.axes()) : null;
      const options = postOptions(p, numbering);
      const stockProblem = stockOf(String(p.stock)) === undefined ? [t('milling.note.stock')] : [];
      /** @type {FixedPart} */
      const fixedPart = {
        bounds: target ? bounds(given, all, target) : bounds(given, all),
        camera: { yaw: -1.9, pitch: 0.55 },
        scale,
        tolerance: Number(p.tolerance),
        units: p.units === 'inch' ? 'inch' : 'mm',
        stride: 2 ** steps,
        layers,
        head: [
          { label: 'milling.readout.poses', value: refined.length },
          ...(profile ? [{ label: 'milling.readout.deviation', value: deviation }] : []),
        ],
        middle: [
          { label: 'milling.readout.angleStep', value: (quality.maxAngleStep * 180) / Math.PI },
          { label: 'milling.readout.secondDifference', value: quality.maxSecondDifference },
          ...(profile ? [{ label: 'milling.readout.compare.given', value: given0 }] : []),
          ...(steps > 0 && profile
            ? Object.entries(compare).map(([k, v]) => ({ label: `milling.readout.compare.${k}`, value: v }))
            : []),
        ],
        stockProblem,
        // the claims are about the example's own poses, not an edit of them
        claims: edited
          ? []
          : [
              ...(steps > 0 && profile
                ? [
                    {
                      text: 'milling.claim.refined',
                      holds: Math.max(compare.variational, compare.averaged, compare['four-point']) < given0,
                    },
                  ]
                : []),
              ...(steps > 0 && profile
                ? [
                    {
                      text: 'milling.claim.turns',
                      holds: turnsAsSaid(turns),
                    },
                  ]
                : []),
              ...(steps > 0 && profile && Number(p.poses) >= 7
                ? [
                    {
                      text: 'milling.claim.variational',
                      holds:
                        Math.max(compare.variational, compare.averaged) <
                        Math.min(compare['four-point'], compare.linear),
                    },
                  ]
                : []),
            ],
        description: imported
          ? t(edited ? 'milling.describeImportedEdited' : 'milling.describeImported', {
              poses: path.length,
              steps,
              scheme: t(`milling.scheme.${p.scheme}`),
              total: refined.length,
            })
          : t(edited ? 'milling.describeEdited' : 'milling.describe', {
              poses: Number(p.poses),
              steps,
              scheme: t(`milling.scheme.${p.scheme}`),
              total: refined.length,
              deviation,
            }),
        // the handles: every given pose's tip (it carries the tool) and a point on its axis (it
        // turns the tool about the tip)
        input: {
          sets: [poseSet(edited ?? path.segments())],
          values: poseValues(path.quality().angleStep, perPose, 2 ** steps, t),
          from: imported
            ? t('edit.from.importedPoses', { poses: path.length })
            : t('edit.from.poses', { poses: Number(p.poses) }),
        },
        downloads: [
          {
            label: 'milling.download.json',
            filename: 'toolpath.json',
            content: refined.export('json'),
            type: 'application/json',
          },
          { label: 'milling.download.csv', filename: 'toolpath.csv', content: refined.export('csv'), type: 'text/csv' },
        ],
        data: { segments: refined.segments() },
        programFile: programFile(String(p.dialect)),
      };
      const optimise =
        p.optimise && target && poses
          ? { poses, tool: refined.tool, target: Float64Array.from(target), post: options }
          : null;
      if (!inWorker) {
        const built = withPost(fixedPart, post, postError, surface, ctx);
        // "Optimise the poses": in the worker, measured by the program as posted
        if (optimise && post?.deviation) built.later = optimiseLater(built, optimise, post);
        return built;
      }
      const first = withPost(fixedPart, null, null, null, ctx);
      first.note = t('milling.note.posting');
      const job = {
        poses: /** @type {Float64Array} */ (poses),
        tool: refined.tool,
        // the poses are refined already
        refine: /** @type {const} */ ({ scheme: 'bspline', degree: 1, steps: 0 }),
        post: { ...options, target: Float64Array.from(/** @type {ArrayLike<number>} */ (target)) },
        draw: 1,
        sweep: true,
      };
      // the post's share of the progress, the optimisation's the rest
      const share = optimise ? 0.25 : 1;
      first.later = (onProgress) =>
        postInWorker(job, (f) => onProgress(share * f))
          .then(
            (done) => {
              const posted = /** @type {import('../../pkg/cam/ruledlab_cam.js').PostResult} */ ({
                ...done.post,
                text: done.text,
              });
              return { posted, built: withPost(fixedPart, posted, null, done.sweep ?? null, ctx) };
            },
            (e) => {
              if (e?.superseded) throw e;
              return { posted: null, built: withPost(fixedPart, null, e, null, ctx) };
            },
          )
          .then(({ posted, built }) =>
            optimise && posted?.deviation
              ? optimiseLater(built, optimise, posted)((f) => onProgress(share + (1 - share) * f))
              : built,
          );
      return first;
    });
  },
});

/**
 * @typedef {object} FixedPart   what the milling scene shows before and after its post
 * @property {import('../scene.js').Built['bounds']} bounds
 * @property {{ yaw: number, pitch: number }} camera
 * @property {number} scale       program units per unit of the poses
 * @property {number} tolerance   the job's, program units
 * @property {'mm' | 'inch'} units   the job's
 * @property {number} stride      refined poses per given pose
 * @property {import('../scene.js').Layer[]} layers
 * @property {import('../scene.js').Readout[]} head     readouts before the envelope's
 * @property {import('../scene.js').Readout[]} middle   readouts between the envelope's and the post's
 * @property {string[]} stockProblem
 * @property {import('../scene.js').Built['claims']} claims
 * @property {string} description
 * @property {import('../scene.js').Built['input']} input
 * @property {NonNullable<import('../scene.js').Built['downloads']>} downloads
 * @property {import('../scene.js').Built['data']} data
 * @property {string} programFile
 */

/**
 * The milling scene's picture with what its post gave: the stock box, the worst point (of the
 * program as posted, else of the path's own sweep), the post's readouts, warnings, figure and
 * program (or, with neither post nor error, the picture while the post is being made).
 * @param {FixedPart} f
 * @param {import('../../pkg/cam/ruledlab_cam.js').PostResult | null} post
 * @param {unknown} postError
 * @param {import('../../pkg/cam/ruledlab_cam.js').EnvelopeResult | null} surface   the path's own sweep against the target
 * @param {import('../scene.js').Context} ctx
 * @returns {import('../scene.js').Built}
 */
function withPost(f, post, postError, surface, ctx) {
  const { t } = ctx;
  const layers = [...f.layers];
  /** @type {import('../scene.js').Label[]} */
  const labels = [];
  // the stock box (named at its greatest corner: a label, the legend's colours being taken)
  if (post) {
    layers.push({ kind: 'segments', style: 'helper', positions: boxEdges(post.stock, f.scale) });
    labels.push({ at: post.stock[1].map((x) => x / f.scale), text: t('milling.label.stock') });
  }
  const worst = post?.deviation
    ? { at: post.deviation.at.map((x) => x / f.scale), value: post.deviation.largest }
    : surface
      ? { at: Array.from(surface.worstPoint), value: surface.worstDeviation * f.scale }
      : null;
  if (worst) {
    layers.push({ kind: 'points', style: 'resultPoint', positions: f32(worst.at) });
    labels.push({
      at: worst.at,
      text: t('milling.worst', { value: ctx.format(worst.value), units: post?.units ?? f.units }),
    });
  }
  const units = post?.units ?? f.units;
  const pending = !post && postError === null;
  return {
    bounds: f.bounds,
    camera: f.camera,
    layers,
    labels,
    readouts: [
      ...f.head,
      ...(surface && !post?.deviation
        ? [
            { label: `milling.readout.envelope.${units}`, value: Math.abs(surface.worstDeviation) * f.scale },
            {
              label: 'milling.readout.beyond',
              value: Array.from(surface.points).filter((d) => Math.abs(d) * f.scale > f.tolerance).length,
            },
          ]
        : []),
      ...f.middle,
      ...(post
        ? postReadouts(post, ctx.format)
        : pending
          ? []
          : [
              {
                label: 'milling.readout.post',
                value: postError instanceof Error ? postError.message : String(postError),
              },
            ]),
    ],
    problems: [...f.stockProblem, ...(post ? warningTexts(post.warnings, ctx) : [])],
    invalid: f.stockProblem.length ? { stock: f.stockProblem[0] } : undefined,
    claims: f.claims,
    description: f.description,
    diagram: deviationDiagram({ target: surface, scale: f.scale, stride: f.stride, post, t, lang: ctx.lang }),
    input: f.input,
    downloads: [
      ...f.downloads,
      ...(post
        ? [{ label: 'milling.download.gcode', filename: f.programFile, content: post.text, type: 'text/plain' }]
        : []),
    ],
    data: f.data,
  };
}

/**
 * The refined poses optimised against the target in the worker (optimise-job.js), with progress:
 * the optimised tool axes drawn over the path, and the deviation from the target of the program as
 * posted — its largest, its deepest gouge and most material left — of the refined poses and of the
 * optimised ones, in the readout.
 * @param {import('../scene.js').Built} built   what is shown meanwhile
 * @param {import('../optimise-job.js').OptimiseJob} job   the refined poses, their tool, the target, the post's options
 * @param {import('../../pkg/cam/ruledlab_cam.js').PostResult} post   the refined poses' program
 * @returns {(onProgress: (fraction: number) => void) => Promise<import('../scene.js').Built>}
 */
function optimiseLater(built, job, post) {
  const before = post.deviation;
  const u = post.units;
  return (onProgress) =>
    optimiseInWorker(job, onProgress).then((done) => {
      const after = done.posted;
      const largestBefore = Math.abs(before?.largest ?? Number.NaN);
      const largestAfter = after ? Math.abs(after.largest) : Number.NaN;
      return {
        ...built,
        layers: [...built.layers, { kind: 'segments', style: 'optimisedAxis', positions: done.segments }],
        readouts: [
          ...(built.readouts ?? []),
          { label: `milling.readout.optimised.before.${u}`, value: largestBefore },
          { label: `milling.readout.optimised.after.${u}`, value: largestAfter },
          { label: 'milling.readout.optimised.less', value: 100 * (1 - largestAfter / largestBefore) },
          { label: `milling.readout.optimised.gouge.${u}`, value: after ? -after.gouge : Number.NaN },
          { label: `milling.readout.optimised.leave.${u}`, value: after ? after.leave : Number.NaN },
          { label: 'milling.readout.optimised.rounds', value: done.rounds },
        ],
      };
    });
}

/**
 * A job too long to refine and post while the page waits: the given poses drawn at once, then
 * refined and posted in the worker with progress (the view's Cancel stops it); the refined path
 * drawn every k-th tool axis, its program downloadable, the post's numbers in the readout.
 * @param {import('../../pkg/cam/ruledlab_cam.js').ToolPath} path
 * @param {import('../scene.js').Params} p
 * @param {import('../scene.js').Context} ctx
 * @param {{ stride: number, lines?: number[] }} numbering
 * @returns {import('../scene.js').Built}
 */
function largeJob(path, p, ctx, numbering) {
  const { t } = ctx;
  const steps = Number(p.steps);
  // what the picture needs of the path, read now: the scope frees it when create() returns
  const given = path.segmentsF32();
  const count = path.length;
  const expected = (count - 1) * 2 ** steps + 1;
  /** @returns {import('../scene.js').Built} */
  const picture = (/** @type {Float32Array} */ segments, /** @type {string} */ note) => ({
    bounds: bounds(given, segments),
    camera: { yaw: -1.9, pitch: 0.55 },
    layers: [
      { kind: 'segments', style: 'insertedAxis', positions: segments },
      { kind: 'segments', style: 'given', positions: given },
    ],
    readouts: [{ label: 'milling.readout.poses', value: expected }],
    note: note || undefined,
    description: t('milling.describeImported', {
      poses: count,
      steps,
      scheme: t(`milling.scheme.${p.scheme}`),
      total: expected,
    }),
  });
  // the optimisation is offered for the jobs the page refines and posts itself
  const notOptimised = p.optimise ? t('milling.note.notOptimised', { max: POST_WORKER_THRESHOLD }) : '';
  const first = picture(
    new Float32Array(0),
    [t('milling.note.large', { poses: expected }), notOptimised].filter(Boolean).join(' '),
  );
  const job = {
    poses: path.tips().length ? interleave(path.tips(), path.axes()) : new Float64Array(0),
    tool: drawnTool(p),
    refine: { ...SCHEMES[/** @type {keyof typeof SCHEMES} */ (p.scheme)], steps },
    // your target, where you gave one: the program as posted is measured against it
    post: { ...postOptions(p, numbering), ...(ctx.data?.target ? { target: ctx.data.target } : {}) },
    draw: DRAW_LIMIT,
  };
  first.later = (onProgress) =>
    postInWorker(/** @type {import('../post-job.js').PostJob} */ (job), onProgress).then((done) => {
      const built = picture(
        done.segments,
        [done.every > 1 ? t('milling.note.drawn', { every: done.every, poses: done.poses }) : '', notOptimised]
          .filter(Boolean)
          .join(' '),
      );
      built.readouts = [
        { label: 'milling.readout.poses', value: done.poses },
        { label: 'milling.readout.angleStep', value: (done.maxAngleStep * 180) / Math.PI },
        ...postReadouts(
          /** @type {import('../../pkg/cam/ruledlab_cam.js').PostResult} */ ({ ...done.post, text: '' }),
          ctx.format,
        ),
      ];
      built.problems = warningTexts(done.post.warnings, ctx);
      built.downloads = [
        {
          label: 'milling.download.gcode',
          filename: programFile(String(p.dialect)),
          content: done.text,
          type: 'text/plain',
        },
      ];
      return built;
    });
  return first;
}

/** Tips and axes (3 numbers each) as 6 numbers per pose. */
function interleave(/** @type {Float64Array} */ tips, /** @type {Float64Array} */ axes) {
  const out = new Float64Array(2 * tips.length);
  for (let i = 0; i < tips.length / 3; i++) {
    out.set(tips.subarray(3 * i, 3 * i + 3), 6 * i);
    out.set(axes.subarray(3 * i, 3 * i + 3), 6 * i + 3);
  }
  return out;
}
