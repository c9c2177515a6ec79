// The striction figure (Section 2, Figs. 2–3, Example 1): a sampled analytic surface with its
// common perpendiculars, the striction polygon m_i of Proposition 2, Fig. 3's polygon of the
// perpendiculars' midpoints, the exact striction curve, the measured orders and the linear
// complex. Drawn by the striction scene and "Your surface"; on the reader's edit of the rulings
// (no exact surface then: no errors, no exact curve, no orders).
import { stripIndices } from '../../pkg/ruledlab.js';
import { bounds, f32 } from '../scene.js';
import { DATA_COMPLEX_TOLERANCE, ROUNDING } from '../limits.js';
import { footpointTargets, parallelProblems, rulingSet, rulingValues, strictionTargets } from '../edit/sets.js';
import { least } from '../reduce.js';

/**
 * The striction figure of a discrete ruled surface: a sample of an analytic surface with
 * `ranges` ({uMin, uMax, vMin, vMax, closed}), compared with it, or — `analytic` null — the
 * reader's edit of such a sample. Shared with "Your surface".
 * @param {import('../../pkg/ruledlab.js').RuledSurface} surface   the rulings drawn (and edited)
 * @param {import('../../pkg/ruledlab.js').AnalyticSurface | null} analytic   the surface they sample; null for an edit
 * @param {{uMin: number, uMax: number, vMin?: number, vMax?: number, closed: boolean}} ranges
 * @param {{n: number, strip: boolean, normals: boolean, polygon: boolean, midpoints: boolean, exact: boolean, axis?: boolean}} p
 * @param {import('../scene.js').Context} ctx
 * @param {string} name   the surface's name, for the description
 * @param {boolean} [orders]   also measure the orders, halving the spacing (the built-in surfaces,
 *   about which the text makes its claim)
 * @param {string | null} [from]   what the surface is, for its handles (the striction scene): the
 *   rulings' endpoints, snapping onto the footpoints and striction points drawn, with φ, h, δ
 *   beside a moving end
 * @returns {import('../scene.js').Built}
 */
export function strictionLayers(surface, analytic, ranges, p, ctx, name, orders = false, from = null) {
  const { t } = ctx;
  const closed = ranges.closed;
  const n = surface.length;
  const segments = surface.segmentsF32();
  const inv = surface.invariants({ closed });
  const errors = analytic?.samplingErrors(p.n, ranges) ?? null;
  const exact = analytic?.striction(analytic.parameters(closed ? 400 : 401, ranges)) ?? null;
  /** @type {import('../scene.js').Layer[]} */
  const layers = [{ kind: 'segments', style: 'ruling', positions: segments }];
  if (p.normals) {
    layers.push({ kind: 'segments', style: 'normal', positions: f32(inv.footpoints) });
    layers.push({ kind: 'points', style: 'foot', positions: f32(inv.footpoints) });
  }
  if (p.exact && exact) layers.push({ kind: 'polyline', style: 'exact', positions: f32(exact), closed });
  if (p.midpoints) {
    layers.push({
      kind: 'polyline',
      style: 'perpendicularMidpoints',
      positions: f32(inv.perpendicularMidpoints),
      closed,
    });
    layers.push({ kind: 'points', style: 'perpendicularMidpoint', positions: f32(inv.perpendicularMidpoints) });
  }
  if (p.polygon) {
    layers.push({ kind: 'polyline', style: 'striction', positions: f32(inv.striction), closed });
    layers.push({ kind: 'points', style: 'strictionPoint', positions: f32(inv.striction) });
  }
  if (p.strip) layers.push({ kind: 'mesh', style: 'strip', positions: segments, indices: stripIndices(n, closed) });
  // beyond the paper: the linear complex that fits the rulings (the book: guide/focal.md)
  const complex = surface.linearComplex({ tolerance: DATA_COMPLEX_TOLERANCE });
  if (p.axis && complex.kind !== 'general' && Number.isFinite(complex.axisSegment[0])) {
    layers.push({ kind: 'segments', style: 'complexAxis', positions: f32(complex.axisSegment) });
  }
  /** @type {import('../scene.js').Readout[]} */
  const measured = [];
  /** @type {import('../scene.js').Claim[]} */
  const claims = [];
  if (orders && analytic) {
    // measured by the core: the errors at N rulings against the spacing halved
    const orders = analytic.samplingOrders(p.n, ranges);
    const o = { footpoint: orders.footpoint, midpoint: orders.midpoint, perpendicular: orders.perpendicularMidpoint };
    for (const [k, v] of Object.entries(o))
      measured.push({ label: `striction.readout.order.${k}`, value: Number.isFinite(v) ? v : 'readout.none' });
    if (ORDER_SURFACES.includes(name) && p.n >= 20) {
      const near = (/** @type {number} */ x, /** @type {number} */ target) => Math.abs(x - target) <= 0.25;
      claims.push({
        text: 'striction.claim.orders',
        holds: near(o.footpoint, 1) && near(o.midpoint, 2) && near(o.perpendicular, 2),
      });
    }
  }
  // δ̄ of the readout is the middle interior ruling's: marked in the view where it is
  const mid = Math.floor(inv.distributionMean.length / 2);
  const middle = inv.distributionMean.length ? inv.distributionMean[mid] : NaN;
  const midRuling = mid + (inv.distributionMean.length === n ? 0 : 1);
  const midAt = Array.from(inv.striction.subarray(3 * mid, 3 * mid + 3));
  /** @type {import('../scene.js').Label[]} */
  const labels =
    inv.distributionMean.length && midAt.every(Number.isFinite)
      ? [{ at: midAt, text: t('striction.label.meanDelta', { i: midRuling }) }]
      : [];
  /** @type {import('../scene.js').SnapTargets[]} */
  const targets = [];
  if (p.normals) targets.push(footpointTargets(inv.footpoints, n));
  if (p.polygon) targets.push(strictionTargets(inv.striction, n));
  if (p.axis && complex.kind !== 'general' && Number.isFinite(complex.axisSegment[0]))
    targets.push({ kind: 'line', points: Float64Array.from(complex.axisSegment), name: 'snap.complexAxis' });
  const shown = [
    p.normals && t('striction.describe.normals'),
    p.polygon && t('striction.describe.polygon'),
    p.midpoints && t('striction.describe.midpoints'),
    p.exact && exact && t('striction.describe.exact'),
  ].filter(Boolean);
  const parallelPairs = inv.parallel.reduce((a, b) => a + b, 0);
  // the smallest |δ| of a pair of rulings: 0 where two rulings meet (a torsal pair)
  const deltas = Array.from(inv.distribution, Math.abs).filter(Number.isFinite);
  const surfaceName = t(`surface.${name}`);
  const smallest = deltas.length ? least(deltas) : Number.NaN;
  const keyValues = { mid: midRuling, mean: middle, least: smallest };
  return {
    bounds: bounds(segments),
    camera: { yaw: -0.9, pitch: 0.45 },
    layers,
    labels,
    readouts: [
      { label: 'readout.rulings', value: n },
      { label: 'readout.parallelPairs', value: errors?.parallelPairs ?? parallelPairs },
      ...(errors
        ? [
            { label: 'readout.midpointError', value: errors.midpoint, exactZero: true },
            { label: 'readout.footpointError', value: errors.footpoint, exactZero: true },
            {
              label: 'readout.perpendicularMidpointError',
              value: errors.perpendicularMidpoint,
              exactZero: true,
            },
          ]
        : []),
      { label: 'readout.meanDelta', value: middle },
      { label: 'focal.readout.complex', value: t(`complex.kind.${complex.kind}`) },
      ...(complex.kind === 'complex'
        ? [
            {
              label: 'focal.readout.pitch',
              value: Math.abs(complex.pitch) < ROUNDING ? 0 : complex.pitch,
              exactZero: true,
            },
          ]
        : []),
      ...measured,
    ],
    claims,
    measures: { 'striction.minAbsDelta': smallest },
    problems: parallelProblems(inv.parallel, n, t),
    description: errors
      ? t('striction.describe', {
          surface: surfaceName,
          n,
          closed: t(closed ? 'describe.closed' : 'describe.open'),
          shown: shown.length ? shown.join(', ') : t('describe.nothingElse'),
          midpoint: errors.midpoint,
          footpoint: errors.footpoint,
          ...keyValues,
        })
      : t('striction.describeEdited', {
          surface: surfaceName,
          n,
          shown: shown.length ? shown.join(', ') : t('describe.nothingElse'),
          parallel: parallelPairs,
          ...keyValues,
        }),
    data: { segments: surface.segments(), closed },
    ...(from
      ? {
          input: {
            sets: [{ ...rulingSet(surface.segments(), undefined, closed), targets }],
            from,
            values: rulingValues(inv, n, t),
          },
        }
      : {}),
  };
}

/** The surfaces on which the text claims the orders 1, 2, 2 (the others are exact or degenerate). */
const ORDER_SURFACES = ['hyperboloid', 'quartic'];

/**
 * The exact striction curve s(u) (3 numbers per u) or distribution parameter δ(u) of an analytic
 * surface at `samples` parameters over its range (Scene.exact: what a typed answer is compared
 * with).
 * @param {import('../../pkg/ruledlab.js').AnalyticSurface} analytic
 * @param {{uMin: number, uMax: number, closed: boolean}} ranges
 * @param {'striction' | 'distribution'} kind
 * @param {number} samples
 */
export function exactCurve(analytic, ranges, kind, samples) {
  const u = analytic.parameters(samples, { ...ranges, closed: false });
  return { u, values: kind === 'striction' ? analytic.striction(u) : analytic.distribution(u) };
}
