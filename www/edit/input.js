// The reader's edit of a scene's input (Input of scene.js: one Float64Array of xyz per handle
// set) in a link and back, bit for bit: each set as its key, a dot, and the little-endian bytes of
// its doubles in base64url ("rulings.AAAAAAAA8D8…"), sets joined by "~". Also the checks that an
// edit fits the scene it is given to, and the copies and comparisons undo needs.
import { MAX_LINK_HANDLES } from '../limits.js';
import { fromBase64url, toBase64url } from '../base64url.js';

/** Doubles as little-endian bytes (whatever the machine's order). */
function bytesOf(/** @type {Float64Array} */ values) {
  const view = new DataView(new ArrayBuffer(values.length * 8));
  for (let i = 0; i < values.length; i++) view.setFloat64(8 * i, values[i], true);
  return new Uint8Array(view.buffer);
}

/** How many handles an edit has (3 numbers each). */
export function handleCount(/** @type {import('../scene.js').Input} */ input) {
  return Object.values(input).reduce((n, v) => n + v.length / 3, 0);
}

/** Whether an edit is small enough for a link (MAX_LINK_HANDLES handles). */
export function linkableInput(/** @type {import('../scene.js').Input} */ input) {
  return handleCount(input) <= MAX_LINK_HANDLES;
}

/** The link text of an edit (bit for bit). */
export function encodeInput(/** @type {import('../scene.js').Input} */ input) {
  return Object.entries(input)
    .map(([key, values]) => `${key}.${toBase64url(bytesOf(values))}`)
    .join('~');
}

/**
 * Reads `encodeInput`'s text; null when it is not that (a key that is not a word, bytes that
 * are not whole points, a number that is not finite).
 * @param {string} text
 * @returns {import('../scene.js').Input | null}
 */
export function decodeInput(text) {
  /** @type {import('../scene.js').Input} */
  const input = {};
  for (const part of String(text).split('~')) {
    const m = /^([a-z][a-zA-Z0-9]{0,31})\.([A-Za-z0-9_-]*)$/.exec(part);
    if (!m || m[1] in input) return null;
    const bytes = fromBase64url(m[2]);
    if (!bytes || bytes.length === 0 || bytes.length % 24 !== 0) return null;
    const view = new DataView(bytes.buffer);
    const values = new Float64Array(bytes.length / 8);
    for (let i = 0; i < values.length; i++) values[i] = view.getFloat64(8 * i, true);
    if (!values.every(Number.isFinite)) return null;
    input[m[1]] = values;
  }
  return Object.keys(input).length ? input : null;
}

/** A deep copy of an edit. */
export function copyInput(/** @type {import('../scene.js').Input} */ input) {
  return Object.fromEntries(Object.entries(input).map(([k, v]) => [k, Float64Array.from(v)]));
}

/** The input of handle sets, copied. */
export function inputOf(/** @type {import('../scene.js').HandleSet[]} */ sets) {
  return Object.fromEntries(sets.map((s) => [s.key, Float64Array.from(s.points)]));
}

/** Whether two edits are the same bit for bit (−0 and 0 differ; NaN equals NaN of the same bits). */
export function sameInput(
  /** @type {import('../scene.js').Input | null} */ a,
  /** @type {import('../scene.js').Input | null} */ b,
) {
  if (a === b) return true;
  if (!a || !b) return false;
  const keys = Object.keys(a);
  if (keys.length !== Object.keys(b).length) return false;
  return keys.every((k) => {
    const x = a[k],
      y = b[k];
    if (!y || x.length !== y.length) return false;
    const bx = new Uint8Array(x.buffer, x.byteOffset, x.byteLength),
      by = new Uint8Array(y.buffer, y.byteOffset, y.byteLength);
    return bx.every((v, i) => v === by[i]);
  });
}

/**
 * Whether an edit fits handle sets (the same keys, each with as many points): what a scene can
 * compute on. An edit from a link that does not fit is refused, with a note.
 * @param {import('../scene.js').Input} input
 * @param {import('../scene.js').HandleSet[]} sets
 */
export function fitsSets(input, sets) {
  const keys = Object.keys(input);
  return (
    keys.length === sets.length &&
    sets.every((s) => input[s.key] instanceof Float64Array && input[s.key].length === s.points.length)
  );
}
