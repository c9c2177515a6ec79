// What holds a scene's handles besides the reader's hand and the drag's mode: the constraints an
// exercise declares (its "edit" field) — a handle on a line through it, on a plane through it, or
// fixed — whether a drag snaps, and whether coordinates may be typed. The field is read here (the book: teaching/exercises.md, "Holding the points"):
//
//   "edit": { "snap": true, "typed": true,
//             "constraints": [{ "handle": "rulings.21", "on": "line", "direction": [0, 0, 1] },
//                             { "handle": "points.3", "on": "plane", "normal": [0, 0, 1] },
//                             { "handle": "poses.6", "on": "fixed" }] }
//
// A constraint that cannot hold (a handle the scene does not have, a line without a direction, a
// plane without a normal) is said and lifted when the exercise opens; the core says when a drag
// cannot keep one (the line runs towards the viewer, it misses the box).
import { MAX_TASK_NAMES, MAX_TASK_NUMBER } from '../limits.js';

/**
 * A handle held: by its set's key and its index in the set.
 * @typedef {object} HeldHandle
 * @property {string} handle   "<set key>.<index>", e.g. "rulings.21" (ruling 10, end b)
 * @property {'line' | 'plane' | 'fixed'} on
 * @property {number[]} [direction]   line: its direction (through the handle)
 * @property {number[]} [normal]      plane: its normal (through the handle)
 *
 * An exercise's rules of editing.
 * @typedef {object} EditRules
 * @property {boolean} snap    whether a drag snaps onto the figure (default true)
 * @property {boolean} typed   whether a point's coordinates may be typed (default true)
 * @property {HeldHandle[]} constraints
 */

/** The rules when nothing is declared. */
export const FREE_RULES = Object.freeze({ snap: true, typed: true, constraints: [] });

const HANDLE = /^[a-z]+\.\d{1,6}$/;

/**
 * Reads an exercise's "edit" field; `fail(key, what)` throws the exercise's error for a field
 * that is not what it must be.
 * @param {unknown} x
 * @param {(key: string, what: string) => never} fail
 * @returns {EditRules}
 */
export function readEditRules(x, fail) {
  if (typeof x !== 'object' || x === null || Array.isArray(x))
    return fail('edit', 'an object { "snap", "typed", "constraints" }');
  const o = /** @type {Record<string, unknown>} */ (x);
  for (const k of Object.keys(o))
    if (!['snap', 'typed', 'constraints'].includes(k)) fail(`edit.${k}`, 'one of "snap", "typed", "constraints"');
  const flag = (/** @type {string} */ k) => {
    if (o[k] === undefined) return true;
    return typeof o[k] === 'boolean' ? /** @type {boolean} */ (o[k]) : fail(`edit.${k}`, 'true or false');
  };
  const list = o.constraints ?? [];
  if (!Array.isArray(list) || list.length > MAX_TASK_NAMES)
    fail('edit.constraints', `a list of at most ${MAX_TASK_NAMES} constraints`);
  const constraints = /** @type {unknown[]} */ (list).map((c, i) => {
    const key = `edit.constraints[${i}]`;
    if (typeof c !== 'object' || c === null || Array.isArray(c))
      return fail(key, 'an object { "handle", "on", "direction" or "normal" }');
    const r = /** @type {Record<string, unknown>} */ (c);
    if (typeof r.handle !== 'string' || !HANDLE.test(r.handle))
      fail(`${key}.handle`, 'a handle as "<set>.<index>", e.g. "rulings.21"');
    const on = r.on;
    if (on !== 'line' && on !== 'plane' && on !== 'fixed') return fail(`${key}.on`, '"line", "plane" or "fixed"');
    const vector = on === 'line' ? 'direction' : on === 'plane' ? 'normal' : null;
    for (const k of Object.keys(r))
      if (!['handle', 'on', ...(vector ? [vector] : [])].includes(k))
        fail(`${key}.${k}`, vector ? `"handle", "on" and "${vector}"` : '"handle" and "on"');
    /** @type {HeldHandle} */
    const held = { handle: /** @type {string} */ (r.handle), on };
    if (vector) {
      const v = r[vector];
      if (
        !Array.isArray(v) ||
        v.length !== 3 ||
        !v.every((n) => typeof n === 'number' && Number.isFinite(n) && Math.abs(n) <= MAX_TASK_NUMBER)
      )
        fail(`${key}.${vector}`, 'three finite numbers');
      held[vector] = /** @type {number[]} */ (v).slice();
    }
    return held;
  });
  return { snap: flag('snap'), typed: flag('typed'), constraints };
}

/** The constraints in force on a stage's handles, checked against the handle sets. */
export class Rules {
  constructor() {
    /** @type {EditRules} */
    this.exercise = FREE_RULES;
    /** @type {Map<string, HeldHandle>} by "<set key>.<index>" */
    this.byHandle = new Map();
  }

  /**
   * The constraints for these handle sets; returns the exercise's that cannot hold (lifted), by
   * their handle, with why ("handle": no such handle; "vector": no direction or normal).
   * @param {import('../scene.js').HandleSet[]} sets
   * @param {EditRules | null} exercise
   */
  take(sets, exercise) {
    this.exercise = exercise ?? FREE_RULES;
    this.byHandle = new Map();
    /** @type {Array<{handle: string, why: 'handle' | 'vector'}>} */
    const lifted = [];
    for (const held of this.exercise.constraints) {
      const [key, index] = held.handle.split('.');
      const set = sets.find((s) => s.key === key);
      const vector = held.direction ?? held.normal;
      if (!set || 3 * Number(index) + 2 >= set.points.length) lifted.push({ handle: held.handle, why: 'handle' });
      else if (vector && !vector.some((x) => x !== 0)) lifted.push({ handle: held.handle, why: 'vector' });
      else this.byHandle.set(held.handle, held);
    }
    return lifted;
  }

  /**
   * What holds `handle` (the core's constraint, through its point now), or null.
   * @param {import('./editor.js').Handle} handle
   * @returns {import('./snap.js').DragConstraint | null}
   */
  held(handle) {
    const held = this.byHandle.get(`${handle.key}.${handle.index}`);
    if (!held) return null;
    if (held.on === 'fixed') return { kind: 'fixed', point: handle.point };
    if (held.on === 'line')
      return { kind: 'line', point: handle.point, direction: /** @type {number[]} */ (held.direction) };
    return { kind: 'plane', point: handle.point, normal: /** @type {number[]} */ (held.normal) };
  }

  /** Forgets a constraint the core said cannot hold (it is lifted). */
  lift(/** @type {import('./editor.js').Handle} */ handle) {
    this.byHandle.delete(`${handle.key}.${handle.index}`);
  }
}
