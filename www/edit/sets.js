// The handle sets scenes declare (scene.js: HandleSet) — the rulings' endpoints, the lines of a
// grid, tool poses, control points — and what an edited input leaves undefined, said in words
// from the core's own flags ("rulings 4 and 5 are parallel: δ is undefined there").

/**
 * The endpoints a_i, b_i of rulings (6 numbers per ruling, as the core's `segments()`).
 * @param {Float64Array} segments
 * @param {Float32Array | Float64Array} [transform]   where they are drawn
 * @returns {import('../scene.js').HandleSet}
 */
export function rulingSet(segments, transform) {
  return {
    key: 'rulings',
    points: segments,
    shape: 'pairs',
    name: 'handle.ruling',
    ends: ['handle.end.a', 'handle.end.b'],
    ...(transform ? { transform } : {}),
  };
}

/**
 * The points p and q of every line of a grid (6 numbers per line, row by row).
 * @param {Float64Array} segments
 * @param {number} cols
 * @returns {import('../scene.js').HandleSet}
 */
export function lineSet(segments, cols) {
  return {
    key: 'lines',
    points: segments,
    shape: 'pairs',
    name: 'handle.line',
    ends: ['handle.end.p', 'handle.end.q'],
    cols,
  };
}

/**
 * Tool poses: each pose's tip and the end of its axis (6 numbers per pose). Moving a tip moves
 * the tool (its axis end comes along); moving an axis end turns the tool about its tip.
 * @param {Float64Array} segments
 * @returns {import('../scene.js').HandleSet}
 */
export function poseSet(segments) {
  return {
    key: 'poses',
    points: segments,
    shape: 'pairs',
    name: 'handle.pose',
    ends: ['handle.end.tip', 'handle.end.axis'],
    carry: true,
  };
}

/**
 * Control points of a polygon (3 numbers each).
 * @param {Float64Array} points
 * @returns {import('../scene.js').HandleSet}
 */
export function pointSet(points) {
  return { key: 'points', points, shape: 'points', name: 'handle.point' };
}

/**
 * The parallel pairs of consecutive rulings, in words: the core flags them (`parallel` of its
 * invariants) and leaves δ, the footpoints and the striction point there NaN.
 * @param {ArrayLike<number>} parallel   1 per parallel pair (i, i + 1)
 * @param {number} count   how many rulings (a closed surface's last pair is (N − 1, 0))
 * @param {(key: string, vars?: Record<string, string | number>) => string} t
 * @returns {string[]}
 */
export function parallelProblems(parallel, count, t) {
  const pairs = [];
  for (let i = 0; i < parallel.length; i++) if (parallel[i]) pairs.push(i);
  if (!pairs.length) return [];
  const [i] = pairs;
  const vars = { i: String(i), j: String((i + 1) % count) };
  return [
    pairs.length === 1 ? t('problem.parallel', vars) : t('problem.parallelMany', { ...vars, count: pairs.length }),
  ];
}
