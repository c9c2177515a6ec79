// Numbers drawn per attempt (the exercise's "draw", task/format.js): every student gets her own
// N between 8 and 16 or her own tolerance, from a seed the course system's attempt or the page
// gives, and the exercise is checked for the numbers she got — the scene computes at the drawn
// parameters and the core decides, so nothing is precomputed for a list of variants. The same
// seed draws the same numbers everywhere (page, element, SCORM package, H5P), so an attempt that
// keeps its seed keeps its numbers.
import { TaskError } from './format.js';
import { statedNumber } from './words.js';
import { MAX_SEED } from '../limits.js';

/**
 * @typedef {import('./format.js').Task} Task
 * @typedef {import('./format.js').Draw} Draw
 * @typedef {import('./format.js').Words} Words
 */

/** A fresh seed: 32 random bits (the browser's and Node's crypto). */
export function randomSeed() {
  return globalThis.crypto.getRandomValues(new Uint32Array(1))[0];
}

/**
 * A whole number from 0 to MAX_SEED that a text gives, the same on every machine (FNV-1a, 32
 * bits): the seed of a learner's numbers where the lecturer draws them per learner (her id and the
 * package's), so that every launch of hers — a relaunch, a review — shows the same numbers.
 */
export function seedOf(/** @type {string} */ text) {
  let h = 2166136261;
  for (let i = 0; i < text.length; i++) h = Math.imul(h ^ text.charCodeAt(i), 16777619);
  return (h >>> 0) % (MAX_SEED + 1);
}

/**
 * A number in [0, 1) from `seed` and a label (an exercise's id and a drawn name): FNV-1a of the
 * label started from the seed, then mulberry32's output mix — the same on every machine.
 */
function uniform(/** @type {number} */ seed, /** @type {string} */ label) {
  let h = (2166136261 ^ seed) >>> 0;
  for (let i = 0; i < label.length; i++) h = Math.imul(h ^ label.charCodeAt(i), 16777619);
  let t = (h + 0x6d2b79f5) | 0;
  t = Math.imul(t ^ (t >>> 15), t | 1);
  t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
  return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
}

/** Every value a draw can give, in order (a range's values rounded to 12 digits: 0.3, not 0.30000000000000004). */
export function drawChoices(/** @type {Draw} */ draw) {
  if ('list' in draw) return [...draw.list];
  const count = Math.floor((draw.to - draw.from) / draw.step + 1e-9) + 1;
  return Array.from({ length: count }, (_, k) => Number((draw.from + k * draw.step).toPrecision(12)));
}

/** The value of one draw for `seed` (its first and last possible values are those of drawChoices). */
function drawOne(/** @type {Draw} */ draw, /** @type {number} */ seed, /** @type {string} */ label) {
  const u = uniform(seed, label);
  if ('list' in draw) return draw.list[Math.floor(u * draw.list.length)];
  const count = Math.floor((draw.to - draw.from) / draw.step + 1e-9) + 1;
  return Number((draw.from + Math.floor(u * count) * draw.step).toPrecision(12));
}

/** The numbers `task` draws for `seed`, by name. */
export function drawnValues(/** @type {Task} */ task, /** @type {number} */ seed) {
  return Object.fromEntries(
    Object.entries(task.draw).map(([name, d]) => [name, drawOne(d, seed, `${task.id}:${name}`)]),
  );
}

/** A text with "{name}" replaced by the number drawn, written as the language writes it. */
function fill(
  /** @type {string} */ text,
  /** @type {Record<string, number | string>} */ values,
  /** @type {string} */ lang,
) {
  return text.replace(/\{([A-Za-z][A-Za-z0-9_.-]*)\}/g, (m, k) => {
    if (!Object.keys(values).includes(k)) return m;
    const v = values[k];
    return typeof v === 'number' ? statedNumber(v, lang) : v;
  });
}

/** Words with their placeholders filled, per language. */
function fillWords(/** @type {Words} */ w, /** @type {Record<string, number | string>} */ values) {
  /** @type {Words} */
  const out = {};
  if (w.en !== undefined) out.en = fill(w.en, values, 'en');
  if (w.de !== undefined) out.de = fill(w.de, values, 'de');
  return out;
}

/**
 * `task` with the numbers drawn for `seed`: parameters, bounds and texts hold them, and `drawn`
 * says what was drawn (and keeps the exercise as written, for its link and JSON). An exercise
 * that draws nothing is returned as it is. Throws a TaskError for a seed that is not one.
 * @param {Task} task
 * @param {number} seed
 * @returns {Task}
 */
export function drawTask(task, seed) {
  if (!Number.isInteger(seed) || seed < 0 || seed > MAX_SEED) throw new TaskError('task.error.seed', { max: MAX_SEED });
  const from = task.drawn?.from ?? task;
  if (!Object.keys(from.draw).length) return from;
  const values = drawnValues(from, seed);
  const value = (/** @type {any} */ v) => (v && typeof v === 'object' && 'drawn' in v ? values[v.drawn] : v);
  return {
    ...from,
    title: fillWords(from.title, values),
    prompt: fillWords(from.prompt, values),
    hints: from.hints.map((h) => fillWords(h, values)),
    answers: from.answers.map((a) => ({ ...a, label: fillWords(a.label, values) })),
    params: {
      ...from.params,
      ...Object.fromEntries(Object.entries(from.drawnParams).map(([k, name]) => [k, values[name]])),
    },
    goal: from.goal.map((c) => ({
      ...c,
      ...(c.below !== undefined ? { below: value(c.below) } : {}),
      ...(c.above !== undefined ? { above: value(c.above) } : {}),
      ...(c.near !== undefined ? { near: value(c.near) } : {}),
    })),
    drawn: { seed, values, from },
  };
}

/** Words of an exercise not drawn yet, its "{name}" placeholders said as "…" (a package's title in a course's list). */
export function undrawn(/** @type {Words} */ w, /** @type {Task} */ task) {
  return fillWords(w, Object.fromEntries(Object.keys(task.draw).map((k) => [k, '…'])));
}

/** The drawn numbers as the panel says them ("k = 3, tol = 0.001"), or "" when nothing is drawn. */
export function drawnText(/** @type {Task} */ task, /** @type {string} */ lang) {
  const values = task.drawn?.values ?? {};
  return Object.entries(values)
    .map(([k, v]) => `${k} = ${typeof v === 'number' ? statedNumber(v, lang) : v}`)
    .join(', ');
}
