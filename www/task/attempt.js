// An attempt at an exercise: its seed (the numbers drawn), what the reader may change and has
// changed (parameters, her edit), her answers, the hints she has seen, her checks, and whether she
// has had the solution shown (a shown solution and every check after it earn nothing). The page
// keeps it in the browser where it can (task/progress.js), a SCORM package in the course
// system's suspend_data (page/scorm.js), an H5P activity in H5P's saved state. Whatever comes
// back from there is read here and only here: anything that is not an attempt this code wrote —
// wrong types, absurd numbers, texts too long, markup — is dropped, never shown as markup and
// never thrown at the reader.
import { MAX_SEED, MAX_TASK_HISTORY, MAX_TASK_INPUT, MAX_TEXT_PARAM, MAX_TASK_NAMES } from '../limits.js';

/**
 * @typedef {object} Attempt
 * @property {number | null} seed
 * @property {Record<string, number | string | boolean>} params   the parameters the exercise lets change
 * @property {string | null} input   the reader's edit (edit/input.js's link text)
 * @property {import('./check.js').Answers} answers
 * @property {number} hints
 * @property {import('./panel.js').Check[]} checks
 * @property {boolean} shown   the solution was shown in this attempt (its checks since count for nothing)
 */

const isObject = (/** @type {unknown} */ x) => typeof x === 'object' && x !== null && !Array.isArray(x);
const NAME = /^[A-Za-z][A-Za-z0-9_.-]{0,79}$/;
/** A short text: a string of at most `max` characters, else undefined. */
const short = (/** @type {unknown} */ x, max = MAX_TEXT_PARAM) =>
  typeof x === 'string' && x.length <= max ? x : undefined;
const count = (/** @type {unknown} */ x, /** @type {number} */ max) =>
  Number.isInteger(x) && /** @type {number} */ (x) >= 0 && /** @type {number} */ (x) <= max
    ? /** @type {number} */ (x)
    : undefined;

/**
 * An attempt read from what storage or a course system gave back (null when it is none).
 * @param {unknown} x   parsed JSON
 * @returns {Attempt | null}
 */
export function readAttempt(x) {
  if (!isObject(x)) return null;
  const o = /** @type {Record<string, unknown>} */ (x);
  /** @type {Record<string, number | string | boolean>} */
  const params = {};
  if (isObject(o.params))
    for (const [k, v] of Object.entries(/** @type {Record<string, unknown>} */ (o.params)).slice(0, MAX_TASK_NAMES)) {
      if (!NAME.test(k)) continue;
      if (typeof v === 'boolean' || (typeof v === 'number' && Number.isFinite(v))) params[k] = v;
      else if (short(v) !== undefined) params[k] = /** @type {string} */ (v);
    }
  /** @type {import('./check.js').Answers} */
  const answers = {};
  if (isObject(o.answers))
    for (const [k, v] of Object.entries(/** @type {Record<string, unknown>} */ (o.answers)).slice(0, MAX_TASK_NAMES)) {
      if (!NAME.test(k)) continue;
      if (short(v) !== undefined) answers[k] = /** @type {string} */ (v);
      else if (Array.isArray(v) && v.length === 3 && v.every((t) => short(t) !== undefined))
        answers[k] = /** @type {string[]} */ ([...v]);
    }
  const checks = Array.isArray(o.checks)
    ? o.checks
        .slice(-MAX_TASK_HISTORY)
        .filter(
          (c) =>
            isObject(c) &&
            Number.isFinite(c.at) &&
            Math.abs(c.at) < 1e15 &&
            count(c.of, MAX_TASK_NAMES) !== undefined &&
            count(c.passed, c.of) !== undefined,
        )
        .map((c) => ({
          at: c.at,
          passed: c.passed,
          of: c.of,
          ...(c.shown === 'solution' || c.shown === 'after' ? { shown: c.shown } : {}),
        }))
    : [];
  return {
    seed: count(o.seed, MAX_SEED) ?? null,
    params,
    input: short(o.input, MAX_TASK_INPUT) ?? null,
    answers,
    hints: count(o.hints, MAX_TASK_NAMES) ?? 0,
    checks,
    // (a check made with the solution shown says so too: an attempt trimmed of its older entries keeps it)
    shown: o.shown === true || checks.some((c) => c.shown),
  };
}

/**
 * The best check of an attempt that counts: the most conditions met (null before a first check
 * that counts). The solution shown and the checks made after it count for nothing.
 */
export function bestCheck(/** @type {Pick<Attempt, 'checks'> | null} */ attempt) {
  let best = /** @type {import('./panel.js').Check | null} */ (null);
  for (const c of attempt?.checks ?? []) if (!c.shown && (!best || c.passed / c.of > best.passed / best.of)) best = c;
  return best;
}
