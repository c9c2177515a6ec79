// The handle sets scenes declare (scene.js: HandleSet) — the rulings' endpoints, the lines of a
// grid, tool poses, control points — with what their handles snap onto beside each other (the
// footpoints, the striction points) and the values shown beside a moving ruling's end (φ, h, δ
// of its pairs, read from the core's invariants); and what an edited input leaves undefined,
// said in words from the core's own flags ("rulings 4 and 5 are parallel: δ is undefined there").

/**
 * The endpoints a_i, b_i of rulings (6 numbers per ruling, as the core's `segments()`).
 * @param {Float64Array} segments
 * @param {Float32Array | Float64Array} [transform]   where they are drawn
 * @param {boolean} [closed]   a closed surface: the last ruling and the first are neighbours
 * @returns {import('../scene.js').HandleSet}
 */
export function rulingSet(segments, transform, closed = false) {
  return {
    key: 'rulings',
    points: segments,
    shape: 'pairs',
    name: 'handle.ruling',
    ends: ['handle.end.a', 'handle.end.b'],
    lineName: 'snap.ruling',
    ...(closed ? { closed } : {}),
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
    lineName: 'snap.gridLine',
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
    lineName: 'snap.axis',
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
 * The footpoints f_{i,i+1} (on R_i) and f_{i+1,i} (on R_{i+1}) of the common perpendiculars, as
 * snap targets (the core's `footpoints`: 6 numbers per pair). Where two rulings meet, their
 * footpoints are the point they meet in (the apex of a cone).
 * @param {Float64Array} footpoints
 * @param {number} count   rulings (a closed surface's last pair is (N − 1, 0))
 * @returns {import('../scene.js').SnapTargets}
 */
export function footpointTargets(footpoints, count) {
  const pair = (/** @type {number} */ k) => [k >> 1, ((k >> 1) + 1) % count];
  return {
    kind: 'point',
    points: footpoints,
    name: 'snap.footpoint',
    vars: (k) => {
      const [i, j] = pair(k);
      return k & 1 ? { i: String(j), j: String(i) } : { i: String(i), j: String(j) };
    },
    of: pair,
  };
}

/**
 * The points m_i of the striction polygon (rulings 1 … N − 2, or all of a closed surface's) as
 * snap targets.
 * @param {Float64Array} striction
 * @param {number} count   rulings
 * @returns {import('../scene.js').SnapTargets}
 */
export function strictionTargets(striction, count) {
  const first = striction.length / 3 === count ? 0 : 1;
  const around = (/** @type {number} */ k) => [k + first - 1, k + first, k + first + 1].map((i) => (i + count) % count);
  return {
    kind: 'point',
    points: striction,
    name: 'snap.striction',
    vars: (k) => ({ i: String(k + first) }),
    of: around,
  };
}

/**
 * The values beside a moving end of ruling i: φ, h and δ of its pairs (i − 1, i) and (i, i + 1)
 * and δ̄_i, the striction polygon's value at the ruling, read from the core's invariants
 * (`angle`, `distance`, `distribution`, `distributionMean`).
 * @param {{angle: ArrayLike<number>, distance: ArrayLike<number>, distribution: ArrayLike<number>, distributionMean: ArrayLike<number>}} inv
 * @param {number} count   rulings
 * @param {(key: string, vars?: Record<string, string | number>) => string} t
 * @returns {(set: number, index: number) => import('../scene.js').Readout[]}
 */
export function rulingValues(inv, count, t) {
  const pairs = inv.angle.length;
  const closed = pairs === count;
  const first = inv.distributionMean.length === count ? 0 : 1;
  return (_set, index) => {
    const i = index >> 1;
    /** @type {import('../scene.js').Readout[]} */
    const out = [];
    for (const p of [i - 1, i]) {
      const k = closed ? (p + pairs) % pairs : p;
      if (k < 0 || k >= pairs) continue;
      const vars = { i: String(k), j: String((k + 1) % count) };
      out.push(
        { label: t('value.phi', vars), value: inv.angle[k] },
        { label: t('value.h', vars), value: inv.distance[k], exactZero: true },
        { label: t('value.delta', vars), value: inv.distribution[k], exactZero: true },
      );
    }
    const m = i - first;
    if (m >= 0 && m < inv.distributionMean.length)
      out.push({ label: t('value.deltaMean', { i: String(i) }), value: inv.distributionMean[m], exactZero: true });
    // (a pair of parallel rulings has no δ: said as such, not as NaN)
    return out.map((r) => (Number.isFinite(r.value) ? r : { ...r, value: 'readout.none' }));
  };
}

/**
 * The values beside a moving tool pose k (either handle): its orientation steps, the angles
 * between its axis and its neighbours' in degrees (the core's `quality().angleStep` of the given poses), and
 * the deviation of the refined path at it (`deviationPerPose`, every `stride`-th refined pose is a
 * given one).
 * @param {ArrayLike<number>} angleStep   per pair of given poses
 * @param {ArrayLike<number> | null} perPose   per refined pose, or null without a target profile
 * @param {number} stride
 * @param {(key: string, vars?: Record<string, string | number>) => string} t
 * @returns {(set: number, index: number) => import('../scene.js').Readout[]}
 */
export function poseValues(angleStep, perPose, stride, t) {
  return (_set, index) => {
    const k = index >> 1;
    /** @type {import('../scene.js').Readout[]} */
    const out = [];
    for (const j of [k - 1, k])
      if (j >= 0 && j < angleStep.length)
        out.push({ label: t('value.step', { i: String(j), j: String(j + 1) }), value: (angleStep[j] * 180) / Math.PI });
    if (perPose && k * stride < perPose.length)
      out.push({ label: t('value.deviation', { i: String(k) }), value: perPose[k * stride] });
    return out;
  };
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
