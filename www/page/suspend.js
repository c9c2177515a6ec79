// A SCORM package's attempt as it is kept in the course system's suspend_data (page/course.js):
// the exercise shown, the seed of the numbers drawn, whether the student ended the attempt, the
// interactions' order, and per exercise what she changed, her edit, her answers, the hints she
// saw, her checks and whether the solution was shown. Written compactly, because SCORM 1.2 keeps
// only 4096 characters (CMIString4096): short keys, each check as [time, met, of, mark] with the
// time in seconds in base 36, each interaction as "exercise.condition" indices. What does not fit
// goes in this order: the older checks (never the best that counts, nor the latest), then the
// edits of the exercises not shown, then answers. Read back by readSuspend, which also reads the
// first, longer form ({ v: 1 }) older packages wrote; what comes back is checked by
// task/attempt.js like anything from outside.

/**
 * @typedef {import('../task/attempt.js').Attempt} Attempt
 * @typedef {import('../task/panel.js').Check} Check
 *
 * @typedef {object} Suspended
 * @property {number | null} seed
 * @property {number} at          the exercise shown
 * @property {boolean} ended      the student ended the attempt
 * @property {string[]} order     the interactions' ids, in the order they were first written
 * @property {unknown[]} attempts each exercise's attempt as stored (task/attempt.js reads it)
 */

const MARKS = /** @type {const} */ ({ solution: 1, after: 2 });

/** A check as [seconds in base 36, met, of] (and 1: the solution shown, 2: after it). */
function packCheck(/** @type {Check} */ c) {
  const out = [Math.floor(c.at / 1000).toString(36), c.passed, c.of];
  if (c.shown) out.push(MARKS[c.shown]);
  return out;
}

/** A check back from its packed form (null: not one). */
function unpackCheck(/** @type {unknown} */ x) {
  if (!Array.isArray(x) || typeof x[0] !== 'string' || !/^[0-9a-z]{1,9}$/.test(x[0])) return null;
  const c = { at: Number.parseInt(x[0], 36) * 1000, passed: x[1], of: x[2] };
  return x[3] === 1 ? { ...c, shown: 'solution' } : x[3] === 2 ? { ...c, shown: 'after' } : c;
}

/** An attempt packed (null stays null). */
function pack(/** @type {Attempt | null} */ a) {
  if (!a) return 0;
  /** @type {Record<string, unknown>} */
  const o = {};
  if (Object.keys(a.params).length) o.p = a.params;
  if (a.input) o.n = a.input;
  if (Object.keys(a.answers).length) o.r = a.answers;
  if (a.hints) o.h = a.hints;
  if (a.checks.length) o.c = a.checks.map(packCheck);
  if (a.shown) o.x = 1;
  return o;
}

/** An attempt's stored form back in the shape task/attempt.js reads. */
function unpack(/** @type {unknown} */ x) {
  if (typeof x !== 'object' || x === null || Array.isArray(x)) return null;
  const o = /** @type {Record<string, unknown>} */ (x);
  return {
    params: o.p,
    input: o.n,
    answers: o.r,
    hints: o.h ?? 0,
    checks: Array.isArray(o.c) ? o.c.map(unpackCheck).filter(Boolean) : [],
    shown: o.x === 1,
  };
}

/**
 * The suspend_data of an attempt, at most `limit` characters where trimming can make it so.
 * @param {{seed: number | null, at: number, ended: boolean, order: string[], attempts: Array<Attempt | null>}} state
 * @param {string[]} ids      the exercises' ids, in the package's order
 * @param {number} limit
 * @param {(attempt: Attempt | null) => Check | null} best   the check that counts most (kept)
 */
export function writeSuspend({ seed, at, ended, order, attempts }, ids, limit, best) {
  // an interaction "torsal-pair.c2" as "0.1": its exercise's and its condition's indices
  const index = order.map((id) => {
    const dot = id.lastIndexOf('.c');
    const k = ids.indexOf(id.slice(0, dot));
    return k >= 0 ? `${k}.${Number(id.slice(dot + 2)) - 1}` : null;
  });
  /** @type {Array<Attempt | null>} */
  const copies = attempts.map((a) => a && structuredClone(a));
  const write = () =>
    JSON.stringify({
      v: 2,
      ...(seed === null ? {} : { s: seed }),
      t: at,
      ...(ended ? { e: 1 } : {}),
      i: index.filter((x) => x !== null),
      a: copies.map(pack),
    });
  let text = write();
  const trims = [
    (/** @type {Attempt} */ a) => {
      const keep = best(a);
      a.checks = a.checks.filter((c, k) => c === keep || k === a.checks.length - 1);
    },
    (/** @type {Attempt} */ a, /** @type {number} */ k) => {
      if (k !== at) a.input = null;
    },
    (/** @type {Attempt} */ a) => {
      a.answers = {};
    },
  ];
  for (const trim of trims) {
    if (text.length <= limit) break;
    copies.forEach((a, k) => {
      if (a) trim(a, k);
    });
    text = write();
  }
  return text;
}

/**
 * What suspend_data holds (either form), or null when it holds nothing this page wrote.
 * @param {string} text
 * @param {string[]} ids   the exercises' ids, in the package's order
 * @returns {Suspended | null}
 */
export function readSuspend(text, ids) {
  let data;
  try {
    data = text ? JSON.parse(text) : null;
  } catch {
    return null;
  }
  if (typeof data !== 'object' || data === null || Array.isArray(data)) return null;
  const strings = (/** @type {unknown} */ x) =>
    Array.isArray(x) ? x.filter((y) => typeof y === 'string').slice(0, 2000) : [];
  if (data.v === 2)
    return {
      seed: data.s ?? null,
      at: data.t,
      ended: data.e === 1,
      order: strings(data.i)
        .map((x) => /^(\d{1,3})\.(\d{1,3})$/.exec(x))
        .filter((m) => m !== null && Number(m[1]) < ids.length)
        .map(
          (m) =>
            `${ids[Number(/** @type {RegExpExecArray} */ (m)[1])]}.c${Number(/** @type {RegExpExecArray} */ (m)[2]) + 1}`,
        ),
      attempts: Array.isArray(data.a) ? data.a.map(unpack) : [],
    };
  // the first form: long keys, checks as objects, interactions by their ids
  return {
    seed: data.seed ?? null,
    at: data.at,
    ended: false,
    order: strings(data.i),
    attempts: Array.isArray(data.a) ? data.a : [],
  };
}
