// The invariants of many rulings (the data scene above its level of detail: a notebook's 10⁶),
// computed off the page and reduced to what the scene shows — the striction curve through the
// rulings drawn, the parallel pairs, the smallest |δ| — with the rulings drawn. Run by the worker
// (worker.js) and, where no worker can start, on the main thread by compute.js: one routine for
// both.
import { RuledSurface } from '../pkg/ruledlab.js';

/**
 * @typedef {object} InvariantsJob
 * @property {Float64Array} segments   6 numbers per ruling
 * @property {boolean} closed          the last ruling followed by the first
 * @property {number} every            the rulings drawn: 0, k, 2k, …, and the last
 *
 * @typedef {object} InvariantsJobResult
 * @property {Float32Array} segments   the rulings drawn (f32, 6 numbers each)
 * @property {Float32Array} striction  the striction curve's points at the rulings drawn (f32)
 * @property {Uint8Array} parallel     1 for each pair of rulings counted parallel
 * @property {number} parallelPairs    how many
 * @property {number} leastDelta       the smallest |δ| of a pair (Infinity where none is finite)
 * @property {number} rulings
 */

/**
 * @param {InvariantsJob} job
 * @param {(fraction: number) => void} progress
 * @param {() => Promise<unknown> | void} [pause]  between the steps (the main thread yields there;
 *   a rejection stops the job)
 * @returns {Promise<InvariantsJobResult>}
 */
export async function invariantsSteps({ segments, closed, every }, progress, pause) {
  const surface = RuledSurface.fromSegments(segments);
  try {
    progress(0.1);
    await pause?.();
    const done = invariantsSummary(surface, closed, every);
    progress(1);
    return done;
  } finally {
    surface.free();
  }
}

/**
 * What the scene shows of `surface`'s invariants, drawn through every `every`-th ruling.
 * @param {RuledSurface} surface @param {boolean} closed @param {number} every
 * @returns {InvariantsJobResult}
 */
export function invariantsSummary(surface, closed, every) {
  const inv = surface.invariants({ closed });
  let parallelPairs = 0;
  for (const p of inv.parallel) parallelPairs += p;
  let leastDelta = Infinity;
  for (const d of inv.distribution) if (Number.isFinite(d)) leastDelta = Math.min(leastDelta, Math.abs(d));
  return {
    segments: surface.everyF32(every),
    striction: everyPoint(inv.striction, every, closed ? 0 : 1),
    parallel: inv.parallel,
    parallelPairs,
    leastDelta,
    rulings: surface.length,
  };
}

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
