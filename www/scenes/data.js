// Your data: rulings (or a congruence) pasted or uploaded as CSV or JSON in the page's data panel,
// handed over by "Edit as data", or sent from a notebook (NumPy arrays), with its invariants.
// "Closed" acts on rulings and "Focal surfaces" on a grid of lines: which one the data is is known
// only once it is read (a control's reason follows its parameters alone), so the other is said
// in a note when it is checked.
import { LineCongruence, RuledSurface, stripIndices, gridIndices } from '../../pkg/ruledlab.js';
import { focalLayers } from '../layers/focal.js';
import { defineScene, scoped, bounds, f32 } from '../scene.js';
import { lineSet, parallelProblems, rulingSet, rulingValues, strictionTargets } from '../edit/sets.js';
import { least, append } from '../reduce.js';
import { DATA_DETAIL_LIMIT, DATA_DRAWN, LINE_LIMIT } from '../limits.js';
import { invariantsSummary } from '../invariants-job.js';

/**
 * What the scene shows before anything is imported: five rulings of a small twisted strip.
 * @type {import('../scene.js').ImportedData}
 */
export const EXAMPLE = {
  segments: new Float64Array([
    0, 0, 0, 1, 0, 0, 0, 0, 0.5, 0.7, 0.7, 0.5, 0, 0, 1, 0, 1, 1, 0, 0, 1.5, -0.7, 0.7, 1.5, 0, 0, 2, -1, 0, 2,
  ]),
};

export const scene = defineScene({
  id: 'data',
  title: 'data.title',
  text: 'data.text',
  params: [
    { key: 'strip', label: 'param.strip', type: 'checkbox', value: true },
    { key: 'closed', label: 'data.param.closed', type: 'checkbox', value: false },
    { key: 'focal', label: 'formulaCongruence.param.focal', type: 'checkbox', value: false },
  ],
  legend: [
    { style: 'ruling', label: 'data.legend.rulings' },
    // the focal checkbox acts on a grid of lines only, and the surface entries on surfaces only:
    // one legend at a time (their colours are shared: normals and focal sheet 1 are both blue)
    { style: 'normal', label: 'legend.normals', when: (p) => !p.focal },
    // (many rulings: drawn as a curve through the rulings drawn, the picture's legendAs says)
    { style: 'striction', label: 'legend.striction', when: (p) => !p.focal },
    { style: 'focal1', label: 'focal.legend.focal1', when: (p) => !!p.focal },
    { style: 'focal2', label: 'focal.legend.focal2', when: (p) => !!p.focal },
    { style: 'torsal', label: 'focal.legend.torsal', when: (p) => !!p.focal },
  ],
  create(p, ctx) {
    const { t, data, input } = ctx;
    // tool poses are the milling scene's
    const imported = data && !data.poses ? data : null;
    const { rows, cols } = imported ?? EXAMPLE;
    // your segments as imported, or as you moved them since
    const segments = input?.lines ?? input?.rulings ?? (imported ?? EXAMPLE).segments;
    const from = t(imported ? 'edit.from.data' : 'edit.from.example');
    return scoped((own) => {
      if (rows && cols) {
        const c = own(LineCongruence.fromGrid(rows, cols, segments));
        const seg = c.segmentsF32();
        /** @type {import('../scene.js').Layer[]} */
        const layers = [{ kind: 'segments', style: 'ruling', positions: seg }];
        if (p.strip)
          layers.push({
            kind: 'mesh',
            style: 'director1',
            positions: c.directorF32(1),
            indices: gridIndices(rows, cols),
          });
        /** @type {import('../scene.js').Readout[]} */
        const readouts = [{ label: 'data.readout.lines', value: `${rows} × ${cols}` }];
        /** @type {Record<string, number>} */
        const measures = {};
        let description = t('data.describeCongruence', { rows, cols });
        if (p.focal) {
          // beyond the paper: the focal geometry of your grid of lines (scene "Focal surfaces")
          const focal = focalLayers(own, c, { sheets: true, torsal: true }, ctx);
          append(
            layers,
            focal.layers.filter((l) => l.kind === 'mesh' || l.style === 'torsal'),
          );
          append(readouts, focal.readouts);
          Object.assign(measures, focal.measures);
          description = `${description} ${focal.sentence}`;
        }
        return {
          bounds: bounds(seg),
          layers,
          readouts,
          measures,
          description,
          ...(p.closed ? { note: t('data.note.closedGrid') } : {}),
          data: { segments, grid: { rows, cols } },
          input: { sets: [lineSet(c.segments(), cols)], from },
        };
      }
      const closed = !!p.closed;
      const s = own(RuledSurface.fromSegments(segments));
      // many rulings: drawn through every k-th of them (the numbers are of all), not editable,
      // their invariants computed in the worker where the page has one
      if (s.length > DATA_DETAIL_LIMIT) {
        const every = Math.ceil(s.length / DATA_DRAWN);
        const job = { segments, closed, every };
        if (!ctx.invariants) return detailed(invariantsSummary(s, closed, every), job, p, ctx);
        const shown = { segments: s.everyF32(every), rulings: s.length };
        const first = detailed(shown, job, p, ctx);
        first.cancelled = detailed(shown, job, p, ctx, true);
        const compute = ctx.invariants;
        first.later = (onProgress) => compute(job, onProgress).then((done) => detailed(done, job, p, ctx));
        return first;
      }
      const inv = s.invariants({ closed });
      const parallel = inv.parallel.reduce((a, b) => a + b, 0);
      const seg = s.segmentsF32();
      const drawn = seg.length / 6;
      const striction = f32(inv.striction);
      /** @type {import('../scene.js').Layer[]} */
      const layers = [
        { kind: 'segments', style: 'ruling', positions: seg },
        { kind: 'segments', style: 'normal', positions: f32(inv.footpoints) },
        { kind: 'polyline', style: 'striction', positions: striction, closed },
        { kind: 'points', style: 'strictionPoint', positions: striction },
      ];
      if (p.strip) layers.push({ kind: 'mesh', style: 'strip', positions: seg, indices: stripIndices(drawn, closed) });
      return {
        bounds: bounds(seg),
        layers,
        readouts: [
          { label: 'readout.rulings', value: s.length },
          { label: 'readout.parallelPairs', value: parallel },
        ],
        description: t('data.describe', {
          n: s.length,
          parallel,
          least: least(Array.from(inv.distribution, Math.abs).filter(Number.isFinite)),
        }),
        problems: parallelProblems(inv.parallel, s.length, t),
        ...(p.focal ? { note: t('data.note.focalRulings') } : {}),
        data: { segments, closed },
        input: {
          sets: [
            {
              ...rulingSet(s.segments(), undefined, closed),
              targets: [strictionTargets(inv.striction, s.length)],
            },
          ],
          from,
          values: rulingValues(inv, s.length, t),
        },
      };
    });
  },
});

/**
 * The picture of many rulings at a level of detail: the rulings and the strip through every k-th
 * of them and, once computed (`striction` given), the striction curve through them, the parallel
 * pairs and the smallest |δ|; not editable.
 * @param {Partial<import('../invariants-job.js').InvariantsJobResult> & {segments: Float32Array, rulings: number}} shown
 * @param {import('../invariants-job.js').InvariantsJob} job
 * @param {import('../scene.js').Params} p @param {import('../scene.js').Context} ctx
 * @param {boolean} [cancelled]  the invariants' computation was cancelled (not in progress)
 * @returns {import('../scene.js').Built}
 */
function detailed(shown, { segments, closed, every }, p, ctx, cancelled = false) {
  const { t } = ctx;
  const { rulings: n, striction, parallel } = shown;
  const seg = shown.segments;
  const drawn = seg.length / 6;
  // as lines, fewer still: thousands of lines merge into a moiré (and cost software WebGL seconds);
  // every k-th and the last of them, at most LINE_LIMIT
  const lineEvery = Math.ceil((drawn - 1) / (LINE_LIMIT - 1));
  const lines = lineEvery > 1 ? scoped((own) => own(RuledSurface.fromSegments(seg)).everyF32(lineEvery)) : seg;
  /** @type {import('../scene.js').Layer[]} */
  const layers = [{ kind: 'segments', style: 'ruling', positions: lines }];
  if (striction) layers.push({ kind: 'polyline', style: 'striction', positions: striction, closed });
  if (p.strip) layers.push({ kind: 'mesh', style: 'strip', positions: seg, indices: stripIndices(drawn, closed) });
  const notes = [
    p.focal ? t('data.note.focalRulings') : '',
    t('data.note.detail', { every, drawn, lines: every * lineEvery, max: DATA_DETAIL_LIMIT }),
    parallel ? '' : t(cancelled ? 'data.note.cancelled' : 'data.note.computing', { n }),
  ].filter(Boolean);
  return {
    bounds: bounds(seg),
    layers,
    readouts: [
      { label: 'readout.rulings', value: n },
      ...(parallel ? [{ label: 'readout.parallelPairs', value: shown.parallelPairs ?? 0 }] : []),
    ],
    description: parallel
      ? t('data.describeDetail', { n, parallel: shown.parallelPairs ?? 0, least: shown.leastDelta ?? Infinity })
      : t(cancelled ? 'data.describeCancelled' : 'data.describePending', { n }),
    problems: parallel ? parallelProblems(parallel, n, t) : [],
    note: notes.join(' '),
    data: { segments },
    legendOff: ['legend.normals', ...(striction ? [] : ['legend.striction'])],
    legendAs: { 'legend.striction': 'data.legend.strictionDetail' },
  };
}
