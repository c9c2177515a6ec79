// Section 4, Figs. 9–10, Example 3: variational interpolatory subdivision of a ruled strip:
// 12 rulings of the quartic surface, one ruling inserted per pair, n = 12, one of the two
// triangulations of Fig. 9 with its notation, spheres at the inserted endpoints A_i (light)
// and B_i (dark).
import { AnalyticSurface, RuledSurface, stripIndices } from '../../pkg/ruledlab.js';
import { defineScene, scoped, bounds, schemeParam } from '../scene.js';
import { ROUNDING } from '../limits.js';
import { rulingSet } from '../edit/sets.js';

const U = { uMin: -1, uMax: 1, closed: false };
/** The least n at which the coupled energy beats the midpoint rule (strip.claim.coupled, measured). */
const COUPLED_FROM = 5;
/** The old ruling whose neighbourhood carries the labels of Fig. 9. */
const LABELLED = 5;

/**
 * The comparisons the text makes, checked against every scheme's distance from the quartic.
 * @param {{midpoint: number, literal: number, coupled: number, averaged: number, fourPoint: number}} compare
 * @param {number} n
 * @returns {import('../scene.js').Claim[]}
 */
function claimsOf(compare, n) {
  const others = Math.min(compare.literal, compare.coupled, compare.averaged);
  const coupledBeats = compare.coupled < compare.midpoint;
  return [
    { text: 'strip.claim.literal', holds: Math.abs(compare.literal - compare.midpoint) <= ROUNDING },
    // coupled beats the midpoint rule from n = 5 on, and not for n = 3, 4: one sentence, checked at every n
    { text: 'strip.claim.coupled', holds: n >= COUPLED_FROM ? coupledBeats : !coupledBeats },
    { text: 'strip.claim.fourPoint', holds: compare.fourPoint < ROUNDING && compare.fourPoint <= others },
  ];
}

export const scene = defineScene({
  id: 'strip',
  title: 'strip.title',
  text: 'strip.text',
  paper: true,
  // an edit of the given rulings replaces the quartic surface (and its faint exact surface)
  fixed: ['exact'],
  params: [
    schemeParam('coupled', () => [
      ['literal', 'strip.scheme.literal'],
      ['coupled', 'strip.scheme.coupled'],
      ['averaged', 'strip.scheme.averaged'],
      ['four-point', 'strip.scheme.fourPoint'],
    ]),
    {
      key: 'n',
      label: 'strip.param.n',
      type: 'range',
      min: 3,
      max: 24,
      step: 1,
      value: 12,
      play: true,
      unless: (p) => (p.scheme === 'four-point' ? 'strip.reason.n' : null),
    },
    {
      key: 'triangulation',
      label: 'strip.param.triangulation',
      type: 'select',
      value: '1',
      refit: false,
      options: () => [
        ['1', 'strip.triangulation.first'],
        ['2', 'strip.triangulation.second'],
        ['none', 'strip.triangulation.none'],
      ],
    },
    { key: 'labels', label: 'strip.param.labels', type: 'checkbox', value: true },
    { key: 'exact', label: 'strip.param.exact', type: 'checkbox', value: true },
  ],
  legend: [
    { style: 'given', label: 'strip.legend.given' },
    { style: 'inserted', label: 'strip.legend.inserted' },
    { style: 'pointA', label: 'strip.legend.a' },
    { style: 'pointB', label: 'strip.legend.b' },
    { style: 'triangulation', label: 'strip.legend.triangulation', when: (p) => p.triangulation !== 'none' },
  ],
  create(p, { t, input }) {
    return scoped((own) => {
      const n = Number(p.n);
      const quartic = own(AnalyticSurface.byName('quartic'));
      // the given rulings (both boundary polygons a_i, b_i): the quartic's, or the reader's edit
      const edited = input?.rulings;
      const surface = own(edited ? RuledSurface.fromSegments(edited) : quartic.sample(12, U));
      /** @type {import('../../pkg/ruledlab.js').SubdivideOptions} */
      const options =
        p.scheme === 'four-point'
          ? { scheme: 'four-point' }
          : { scheme: 'variational', n, variant: /** @type {'coupled' | 'literal' | 'averaged'} */ (p.scheme) };
      const refined = own(surface.subdivide(options));
      // how far the inserted rulings are from the quartic: only for its own rulings (an edit has
      // no exact surface)
      const error = (/** @type {import('../../pkg/ruledlab.js').SubdivideOptions} */ o) =>
        quartic.insertedDistance(own(surface.subdivide(o)), 2, U.uMin, U.uMax);
      const distance = edited ? NaN : quartic.insertedDistance(refined, 2, U.uMin, U.uMax);
      // every scheme at this n, for the comparisons the text makes (and their claims)
      const compare = edited
        ? null
        : {
            midpoint: error({ scheme: 'bspline', degree: 1 }),
            literal: error({ scheme: 'variational', n, variant: 'literal' }),
            coupled: error({ scheme: 'variational', n, variant: 'coupled' }),
            averaged: error({ scheme: 'variational', n, variant: 'averaged' }),
            fourPoint: error({ scheme: 'four-point' }),
          };
      const old = surface.segmentsF32();
      /** @type {import('../scene.js').Layer[]} */
      const layers = [
        { kind: 'segments', style: 'given', positions: old },
        { kind: 'segments', style: 'inserted', positions: refined.insertedF32(2) },
        { kind: 'points', style: 'pointA', positions: refined.endsF32(1, 2) },
        { kind: 'points', style: 'pointB', positions: refined.endsF32(2, 2) },
      ];
      if (p.triangulation !== 'none')
        layers.push({
          kind: 'segments',
          style: 'triangulation',
          positions: refined.triangulationF32(n, Number(p.triangulation)),
        });
      if (p.exact && !edited) {
        const exact = own(quartic.sample(120, U));
        const seg = exact.segmentsF32();
        layers.push({ kind: 'mesh', style: 'surfaceFaint', positions: seg, indices: stripIndices(120) });
      }
      const k = Math.round(n / 3);
      const at = (/** @type {number} */ i, /** @type {number} */ kk) => [...refined.divisionPoint(i, kk, n)];
      const labels = p.labels
        ? [
            { at: at(2 * LABELLED, 0), text: 'a_i' },
            { at: at(2 * LABELLED, n), text: 'b_i' },
            { at: at(2 * LABELLED + 1, 0), text: 'A_i' },
            { at: at(2 * LABELLED + 1, n), text: 'B_i' },
            { at: at(2 * LABELLED + 2, 0), text: 'a_{i+1}' },
            { at: at(2 * LABELLED + 2, n), text: 'b_{i+1}' },
            { at: at(2 * LABELLED, k), text: 'z_{i,k}' },
            { at: at(2 * LABELLED + 1, k), text: 'Z_{i,k}' },
          ]
        : [];
      return {
        bounds: bounds(old),
        camera: { yaw: -2.2, pitch: 0.5 },
        layers,
        labels,
        readouts: [
          { label: 'readout.rulings', value: refined.length },
          ...(compare
            ? [
                { label: 'strip.readout.distance', value: distance, exactZero: true },
                ...Object.entries(compare).map(([k, v]) => ({
                  label: `strip.readout.compare.${k}`,
                  value: v,
                  exactZero: true,
                })),
              ]
            : []),
        ],
        claims: compare ? claimsOf(compare, n) : [],
        description: t(edited ? 'strip.describeEdited' : 'strip.describe', {
          scheme: t(`strip.scheme.${p.scheme === 'four-point' ? 'fourPoint' : p.scheme}`),
          n,
          distance,
        }),
        data: { segments: refined.segments() },
        // the handles: the points of both boundary polygons (the given rulings' ends a_i, b_i)
        input: { sets: [rulingSet(surface.segments())], from: t('edit.from.strip') },
      };
    });
  },
});
