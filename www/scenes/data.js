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
import { DATA_DETAIL_LIMIT } from '../limits.js';

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
      const inv = s.invariants({ closed });
      const parallel = inv.parallel.reduce((a, b) => a + b, 0);
      // many rulings: drawn through every k-th of them (the numbers are of all), not editable
      const every = Math.ceil(s.length / DATA_DETAIL_LIMIT);
      const seg = every > 1 ? s.everyF32(every) : s.segmentsF32();
      const drawn = seg.length / 6;
      const striction = every > 1 ? everyPoint(inv.striction, every, closed ? 0 : 1) : f32(inv.striction);
      /** @type {import('../scene.js').Layer[]} */
      const layers = [
        { kind: 'segments', style: 'ruling', positions: seg },
        ...(every > 1
          ? []
          : /** @type {import('../scene.js').Layer[]} */ ([
              { kind: 'segments', style: 'normal', positions: f32(inv.footpoints) },
            ])),
        { kind: 'polyline', style: 'striction', positions: striction, closed },
        ...(every > 1
          ? []
          : /** @type {import('../scene.js').Layer[]} */ ([
              { kind: 'points', style: 'strictionPoint', positions: striction },
            ])),
      ];
      if (p.strip) layers.push({ kind: 'mesh', style: 'strip', positions: seg, indices: stripIndices(drawn, closed) });
      const notes = [
        p.focal ? t('data.note.focalRulings') : '',
        every > 1 ? t('data.note.detail', { every, drawn, max: DATA_DETAIL_LIMIT }) : '',
      ].filter(Boolean);
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
        ...(notes.length ? { note: notes.join(' ') } : {}),
        data: { segments },
        ...(every > 1
          ? {}
          : {
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
            }),
      };
    });
  },
});

/**
 * The striction curve's points at the rulings drawn (0, k, 2k, …, and the last), as f32: point j
 * belongs to ruling j + `first` (an open strip's curve begins at ruling 1), and the curve keeps
 * its two ends.
 * @param {ArrayLike<number>} points @param {number} every @param {number} first
 */
function everyPoint(points, every, first) {
  const n = points.length / 3;
  const picked = [0];
  for (let r = every; r - first < n - 1; r += every) if (r - first > 0) picked.push(r - first);
  if (n > 1) picked.push(n - 1);
  const out = new Float32Array(3 * picked.length);
  picked.forEach((i, k) => {
    out[3 * k] = points[3 * i];
    out[3 * k + 1] = points[3 * i + 1];
    out[3 * k + 2] = points[3 * i + 2];
  });
  return out;
}
