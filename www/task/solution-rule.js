// When a reader may have an exercise's solution shown — a lecturer's choice, carried by a link
// (`solution=`), the element's `solution` attribute, a SCORM package's or an H5P file's options:
// after a number of checks that did not solve the exercise ("1", the default: after a first
// check), or never ("never"). Whatever it is shown after, a solution counts for nothing
// (task/panel.js).
import { MAX_SOLUTION_AFTER } from '../limits.js';

/** @typedef {import('./panel.js').SolutionRule} SolutionRule */

/** The rule when none is given: after a first check that does not solve the exercise. */
export const DEFAULT_SOLUTION_RULE = Object.freeze({ after: 1 });

/**
 * The rule a text says: "never", or a whole number of checks from 0 to MAX_SOLUTION_AFTER; null
 * when it says none of these (the caller keeps the default and may say so).
 * @param {string | null | undefined} text
 * @returns {SolutionRule | null}
 */
export function readSolutionRule(text) {
  const t = String(text ?? '').trim();
  if (t === 'never') return { after: null };
  if (!/^\d{1,3}$/.test(t)) return null;
  const n = Number(t);
  return n <= MAX_SOLUTION_AFTER ? { after: n } : null;
}

/**
 * The rule as a link, an attribute or a package writes it; null for the default (nothing written).
 * @param {SolutionRule | null | undefined} rule
 */
export function writeSolutionRule(rule) {
  if (!rule || rule.after === DEFAULT_SOLUTION_RULE.after) return null;
  return rule.after === null ? 'never' : String(rule.after);
}
