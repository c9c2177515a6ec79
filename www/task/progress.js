// Which exercises the reader has solved, kept between visits where the browser keeps anything
// (a sandboxed frame keeps nothing: the exercises work, the progress is not kept).
import { kept, keep } from '../platform.js';

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
