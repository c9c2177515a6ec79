// An edit too large for the link (more than MAX_LINK_HANDLES handles) is kept in the tab's
// session storage, for its scene, so that a reload still shows it; the page says so, and says
// when there is no storage to keep it in (a sandboxed frame).
import { copyInput, linkableInput } from '../edit/input.js';
import { hasStorage, store, stored } from '../platform.js';

/** Session storage key of an edit too large for the link. */
export const STORED_INPUT = 'ruledlab.input';

/**
 * Keeps `input` of scene `scene` where the link cannot (null or a linkable edit: forgets it);
 * returns the i18n key of the note the page shows about it, or ''.
 * @param {string} scene
 * @param {import('../scene.js').Input | null} input
 */
export function keepInput(scene, input) {
  if (!input || linkableInput(input)) {
    store(STORED_INPUT, null);
    return '';
  }
  const sets = Object.fromEntries(Object.entries(input).map(([k, v]) => [k, Array.from(v)]));
  const kept = hasStorage() && store(STORED_INPUT, JSON.stringify({ scene, sets }));
  return kept ? 'edit.tooLarge' : 'edit.tooLargeNoStorage';
}

/**
 * The edit kept for scene `scene`, or null.
 * @param {string} scene
 * @returns {import('../scene.js').Input | null}
 */
export function keptInput(scene) {
  try {
    const kept = JSON.parse(stored(STORED_INPUT) ?? 'null');
    if (!kept || kept.scene !== scene) return null;
    /** @type {import('../scene.js').Input} */
    const input = {};
    for (const [k, v] of Object.entries(kept.sets)) {
      if (!Array.isArray(v) || !v.every(Number.isFinite)) return null;
      input[k] = new Float64Array(v);
    }
    return copyInput(input);
  } catch {
    return null;
  }
}
