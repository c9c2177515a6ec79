// The 3D image of P⁵ a Klein image is drawn in (the book's chapter "The Klein quadric", the
// core's kleinView): q = cos α x + sin α R_β y at the unit of length ℓ, the three numbers the
// reader steers — the Klein scene's sliders, the sliders of the Klein view beside any scene, the
// link's `klein=α,β,ℓ` and <ruled-view klein="α,β,ℓ">. Their ranges are KLEIN_RANGES (limits.js);
// a value outside is held at the nearest end, between steps at the nearest step. Pure: no core.
import { KLEIN_RANGES } from './limits.js';

/**
 * @typedef {{mix: number, turn: number, unit: number}} KleinProjection
 *   mix: α in degrees, how much of the moment vector is seen; turn: β in degrees, the moment's
 *   turn about z; unit: ℓ, the unit of length the moments are measured in
 */

/** The projection a Klein image is drawn in unless the reader steers it (the Klein scene's defaults). */
export const KLEIN_PROJECTION = Object.freeze({ mix: 30, turn: 90, unit: 1 });

/** The three numbers in the order the link and the attribute write them. */
export const PROJECTION_KEYS = /** @type {const} */ (['mix', 'turn', 'unit']);

/** The digits after the decimal point of a step (0.05 → 2). @param {number} step */
const decimals = (step) => (String(step).split('.')[1] ?? '').length;

/**
 * `value` held in the range of `key`: at the nearest end outside it, on the nearest step inside,
 * written with the step's digits (so that 0.1 + 0.2 reads 0.3).
 * @param {keyof typeof KLEIN_RANGES} key
 * @param {number} value
 */
export function holdValue(key, value) {
  const { min, max, step } = KLEIN_RANGES[key];
  const inside = Math.min(max, Math.max(min, value));
  const stepped = min + Math.round((inside - min) / step) * step;
  return Number(Math.min(max, stepped).toFixed(decimals(step)));
}

/**
 * A projection with each number held in its range and on its step, and whether any was moved.
 * @param {KleinProjection} projection
 * @returns {{projection: KleinProjection, held: boolean}}
 */
export function holdProjection(projection) {
  const held = /** @type {KleinProjection} */ ({ ...KLEIN_PROJECTION });
  let moved = false;
  for (const key of PROJECTION_KEYS) {
    held[key] = holdValue(key, projection[key]);
    if (held[key] !== projection[key]) moved = true;
  }
  return { projection: Object.freeze(held), held: moved };
}

/**
 * The projection of a link's or an attribute's text "α,β,ℓ": null for an empty text (the
 * scene's own image), undefined for a text that is not three numbers; numbers outside their
 * ranges are held (`held` says so).
 * @param {string | null} text
 * @returns {{projection: KleinProjection | null, held: boolean} | undefined}
 */
export function readProjection(text) {
  const trimmed = String(text ?? '').trim();
  if (trimmed === '') return { projection: null, held: false };
  const parts = trimmed.split(',').map((x) => (x.trim() === '' ? NaN : Number(x)));
  if (parts.length !== 3 || !parts.every(Number.isFinite)) return undefined;
  const [mix, turn, unit] = parts;
  return holdProjection({ mix, turn, unit });
}

/** The link's and the attribute's text of a projection: "α,β,ℓ". @param {KleinProjection} p */
export function writeProjection(p) {
  return PROJECTION_KEYS.map((key) => String(p[key])).join(',');
}

/** Whether two projections are the same image. @param {KleinProjection | null} a @param {KleinProjection | null} b */
export function sameProjection(a, b) {
  return a === b || (!!a && !!b && PROJECTION_KEYS.every((key) => a[key] === b[key]));
}
