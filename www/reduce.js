// Reductions and appends over data without spreading it into a call: an engine takes some 10⁵
// arguments at most (V8 about 125 000), so Math.min(...values) throws RangeError on the
// distribution parameters of 10⁶ rulings. tests/node/spreads.test.mjs keeps such spreads out of
// www/.

/**
 * The least of `values` and `start`, as Math.min(start, ...values) gives it (Infinity for none,
 * NaN where one is NaN).
 * @param {Iterable<number>} values @param {number} [start]
 */
export function least(values, start = Infinity) {
  let m = start;
  for (const v of values) m = Math.min(m, v);
  return m;
}

/**
 * The greatest of `values` and `start`, as Math.max(start, ...values) gives it (-Infinity for
 * none, NaN where one is NaN).
 * @param {Iterable<number>} values @param {number} [start]
 */
export function greatest(values, start = -Infinity) {
  let m = start;
  for (const v of values) m = Math.max(m, v);
  return m;
}

/**
 * Appends `items` to `list` one by one, as list.push(...items) does without the spread; gives
 * `list`.
 * @template T @param {T[]} list @param {Iterable<T>} items
 */
export function append(list, items) {
  for (const item of items) list.push(item);
  return list;
}
