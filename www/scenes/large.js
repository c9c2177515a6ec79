// Large models: a helicoid of up to 10 000 rulings refined by up to seven four-point steps
// (up to 1 280 000 rulings) in a Web Worker with progress and cancel, the page answering
// meanwhile. Above what the view draws smoothly, a level of detail is drawn (every k-th
// ruling), and the readout says so.
import { AnalyticSurface, RuledSurface, meshNormalsF32, stripIndices } from '../../pkg/ruledlab.js';
import { defineScene, scoped, bounds } from '../scene.js';
import { WORKER_THRESHOLD, DRAW_LIMIT, MOVING_LIMIT, LINE_LIMIT } from '../limits.js';

/**
 * The strip with every k-th ruling of `segments`, at most MOVING_LIMIT, to draw while the
 * camera moves; undefined when the strip is light enough already.
 * @param {Float32Array} segments
 * @returns {import('../scene.js').Layer | undefined}
 */
function movingStrip(segments) {
  const every = Math.ceil(segments.length / 6 / MOVING_LIMIT);
  if (every <= 1) return undefined;
  const coarse = scoped((own) => own(RuledSurface.fromSegments(segments)).everyF32(every));
  const indices = stripIndices(coarse.length / 6);
  return { kind: 'mesh', style: 'stripOpaque', positions: coarse, indices, normals: meshNormalsF32(coarse, indices) };
}

/**
 * @param {Float32Array} segments
 * @param {number} rulings   of the model (drawn: segments.length / 6)
 * @param {boolean} drawRulings
 * @param {import('../scene.js').Context} ctx
 * @returns {import('../scene.js').Built}
 */
function picture(segments, rulings, drawRulings, { t }) {
  const drawn = segments.length / 6;
  const indices = stripIndices(drawn);
  // thousands of rulings put several facets in a pixel: shaded by vertex normals, not by facet
  /** @type {import('../scene.js').Layer[]} */
  const layers = [
    {
      kind: 'mesh',
      style: 'stripOpaque',
      positions: segments,
      indices,
      normals: meshNormalsF32(segments, indices),
      moving: movingStrip(segments),
    },
  ];
  const every = Math.ceil(drawn / LINE_LIMIT);
  let lines = 0;
  if (drawRulings) {
    const shown = scoped((own) => (every > 1 ? own(RuledSurface.fromSegments(segments)).everyF32(every) : segments));
    lines = shown.length / 6;
    layers.push({ kind: 'segments', style: 'ruling', positions: shown });
  }
  const notes = [
    drawn < rulings ? t('large.note.lod', { every: Math.ceil(rulings / drawn), drawn }) : '',
    drawRulings && lines < rulings
      ? t('large.note.lines', { every: Math.round((rulings - 1) / Math.max(lines - 1, 1)) })
      : '',
  ];
  return {
    bounds: bounds(segments),
    camera: { yaw: -1.0, pitch: 0.3 },
    layers,
    readouts: [
      { label: 'large.readout.rulings', value: rulings },
      { label: 'large.readout.drawn', value: drawn },
      ...(drawRulings ? [{ label: 'large.readout.lines', value: lines }] : []),
    ],
    note: notes.filter(Boolean).join(' ') || undefined,
    description: t('large.describe', { rulings, drawn }),
  };
}

export const scene = defineScene({
  id: 'large',
  title: 'large.title',
  text: 'large.text',
  params: [
    { key: 'n', label: 'param.rulings', type: 'range', min: 100, max: 10000, step: 100, value: 2000 },
    { key: 'steps', label: 'large.param.steps', type: 'range', min: 0, max: 7, step: 1, value: 0 },
    { key: 'rulings', label: 'large.param.rulings', type: 'checkbox', value: false },
  ],
  legend: [
    { style: 'stripOpaque', label: 'large.legend.strip' },
    { style: 'ruling', label: 'legend.rulings', when: (p) => !!p.rulings },
  ],
  create(p, ctx) {
    return scoped((own) => {
      const n = Number(p.n),
        steps = Number(p.steps);
      const helicoid = own(AnalyticSurface.byName('helicoid'));
      const coarse = own(helicoid.sample(n, { uMin: 0, uMax: 12, closed: false }));
      const expected = (n - 1) * 2 ** steps + 1;
      if (expected <= WORKER_THRESHOLD || !ctx.refine) {
        const refined = steps ? own(coarse.subdivide({ scheme: 'four-point', steps })) : coarse;
        const every = Math.max(1, Math.ceil(refined.length / DRAW_LIMIT));
        return picture(every > 1 ? refined.everyF32(every) : refined.segmentsF32(), refined.length, !!p.rulings, ctx);
      }
      const first = picture(coarse.segmentsF32(), n, !!p.rulings, ctx);
      const input = coarse.segments();
      const refine = ctx.refine;
      first.later = (onProgress) =>
        refine(input, { scheme: 'four-point', steps }, onProgress, DRAW_LIMIT).then(({ segments, rulings }) =>
          picture(segments, rulings, !!p.rulings, ctx),
        );
      return first;
    });
  },
});
