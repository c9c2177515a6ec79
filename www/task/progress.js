// Which exercises the reader has solved, and her attempt at each (seed, answers, hints, checks),
// kept between visits where the browser keeps anything (a sandboxed frame keeps nothing: the
// exercises work, the progress is not kept).
import { kept, keep } from '../platform.js';
import { readAttempt } from './attempt.js';

/** Lasting storage key of the progress. */
export const PROGRESS = 'ruledlab.progress';

/** The ids of the exercises solved so far. */
export function solvedTasks() {
  try {
    const data = JSON.parse(kept(PROGRESS) ?? '{}');
    return new Set(Object.keys(data).filter((id) => data[id]?.solved === true));
  } catch {
    return new Set();
  }
}

/** Notes that exercise `id` is solved; false where nothing can be kept. */
export function markSolved(/** @type {string} */ id) {
  let data = {};
  try {
    data = JSON.parse(kept(PROGRESS) ?? '{}') ?? {};
  } catch {}
  return keep(PROGRESS, JSON.stringify({ ...data, [id]: { solved: true, at: new Date().toISOString() } }));
}

/** Lasting storage key of an exercise's attempt (its seed, answers, hints and checks). */
const ATTEMPT = 'ruledlab.attempt.';

/**
 * The attempt at exercise `id` kept in this browser (read by task/attempt.js), or null.
 * @param {string} id
 */
export function keptAttempt(id) {
  try {
    return readAttempt(JSON.parse(kept(ATTEMPT + id) ?? 'null'));
  } catch {
    return null;
  }
}

/**
 * Keeps the attempt at exercise `id` in this browser; false where nothing can be kept.
 * @param {string} id
 * @param {import('./attempt.js').Attempt} attempt
 */
export function keepAttempt(id, attempt) {
  return keep(ATTEMPT + id, JSON.stringify(attempt));
}
