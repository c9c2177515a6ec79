// The exercise format (the book: teaching/exercises.md): a small JSON document a lecturer writes (or the
// page writes for her: task/author.js) and the page checks. Read here into a Task, or refused
// with a clear message: unknown keys, wrong types, numbers that are not finite or absurdly large,
// texts too long, conditions of the wrong shape. Whether the values a condition names exist in
// its scene is checked against the scene (task/check.js). Texts are only ever shown as text.
//
// {
//   "ruledlab": "exercise", "version": 1, "id": "torsal-ruling",
//   "title": { "en": "…", "de": "…" }, "prompt": { "en": "…", "de": "…" },
//   "scene": "striction", "params": { "n": 8 }, "input": "rulings.…", "camera": "…",
//   "change": ["handles", "n"], "hide": ["exact", "readout.midpointError"],
//   "answers": [{ "id": "s", "kind": "curve", "label": { "en": "s(u)" } }],
//   "goal": [{ "value": "striction.minAbsDelta", "below": 0.01 },
//            { "answer": "s", "matches": "striction", "within": 1e-6 }],
//   "hints": [{ "en": "…" }], "solution": { "params": {…}, "input": "…", "answers": { "s": ["u", "0", "0"] } },
//   "draw": { "k": { "from": 2, "to": 4 }, "tol": { "list": [0.002, 0.001] } }
//   "edit": { "snap": true, "typed": true, "constraints": [{ "handle": "rulings.21", "on": "line", "direction": [0, 0, 1] }] }
// }
// Drawn numbers (task/draw.js): a parameter's value `{ "drawn": "k" }`, a bound `{ "drawn": "tol" }`
// and "{k}" in the texts take the number drawn for the attempt from its seed.

import { plainSubscripts } from '../ui/richtext.js';
import { fromBase64url, toBase64url } from '../base64url.js';
import {
  MAX_TASK,
  MAX_TASK_ANSWERS,
  MAX_TASK_CAMERA,
  MAX_TASK_DETAIL,
  MAX_TASK_GOAL,
  MAX_TASK_HINTS,
  MAX_TASK_ID,
  MAX_TASK_INPUT,
  MAX_TASK_NAME,
  MAX_TASK_NAMES,
  MAX_TASK_NUMBER,
  MAX_TASK_SAMPLES,
  MAX_TASK_TEXT,
  MAX_TASK_TITLE,
  MAX_TEXT_PARAM,
  MAX_TASK_DRAWS,
  MAX_DRAW_LIST,
  MAX_DRAW_CHOICES,
  MAX_SEED,
} from '../limits.js';
import { readEditRules } from '../edit/rules.js';

/** What `hide` may name besides parameters and readouts: the claims under the readout, the explanation. */
export const HIDE_WORDS = ['claims', 'text'];
/** An exercise's id: a lowercase letter or digit, then letters, digits and dashes, MAX_TASK_ID in all. */
const ID = new RegExp(`^[a-z0-9][a-z0-9-]{0,${MAX_TASK_ID - 1}}$`);
/** A name: a letter, then letters, digits, "_", "." and "-", MAX_TASK_NAME in all. */
const NAME = new RegExp(`^[A-Za-z][A-Za-z0-9_.-]{0,${MAX_TASK_NAME - 1}}$`);
/** MAX_TASK_NUMBER as the reasons say it ("1e12"). */
const LARGEST_NUMBER = MAX_TASK_NUMBER.toExponential().replace('+', '');

/**
 * Words in the languages of the page (at least one; a reader of the other sees the one there is).
 * @typedef {{en?: string, de?: string}} Words
 *
 * An answer field: a number, one formula in u (a function such as δ(u)), or three (a curve
 * such as s(u)).
 * @typedef {object} Answer
 * @property {string} id
 * @property {'number' | 'function' | 'curve'} kind
 * @property {Words} label
 *
 * A condition of the goal, on a value the scene computes (a readout's key or a measure's name)
 * or on an answer.
 * @typedef {object} Condition
 * @property {string} [value]     the value it is about
 * @property {string} [answer]    or the answer it is about
 * @property {Bound} [below]   holds when the value is below this (a number, another value, or a number drawn)
 * @property {Bound} [above]
 * @property {Bound} [near]    holds within `within` of this
 * @property {number} [within]
 * @property {'striction' | 'distribution'} [matches]   a typed curve or function against the exact one
 * @property {number} [samples]   at how many points (default 50)
 *
 * A bound of a condition: a number, a value the scene computes, or a number drawn (until drawn).
 * @typedef {number | {value: string} | {drawn: string}} Bound
 *
 * A number drawn per attempt: from a range (`step` 1 unless given) or from a list.
 * @typedef {{from: number, to: number, step: number} | {list: Array<number | string>}} Draw
 *
 * What an attempt drew (task/draw.js): its seed, the numbers, and the exercise as written.
 * @typedef {object} Drawn
 * @property {number} seed
 * @property {Record<string, number | string>} values
 * @property {Task} from
 *
 * @typedef {object} TaskState
 * @property {Record<string, number | string | boolean>} [params]
 * @property {string} [input]     an edit, as the link writes it (edit/input.js)
 * @property {Record<string, number | string | string[] | {value: string}>} [answers]   a number
 *   answer may be `{ value }`: what the scene computes in the solution's state
 *
 * An exercise.
 * @typedef {object} Task
 * @property {string} id
 * @property {Words} title
 * @property {Words} prompt
 * @property {string} scene
 * @property {Record<string, number | string | boolean>} params   (a drawn one holds the first value
 *   it can take until the exercise is drawn)
 * @property {Record<string, string>} drawnParams   parameters whose value is drawn: the draw's name
 * @property {string | null} input
 * @property {string | null} camera
 * @property {string[]} change    parameter keys the reader may change, and "handles"
 * @property {string[]} hide      parameter keys (kept, not shown), readout keys (not shown), and the
 *   words "claims" (the sentences under the readout) and "text" (the scene's explanation), where they
 *   would say the answer
 * @property {Answer[]} answers
 * @property {Condition[]} goal
 * @property {Words[]} hints
 * @property {TaskState | null} solution
 * @property {Record<string, Draw>} draw   numbers drawn per attempt, by name
 * @property {Drawn | null} [drawn]   set once drawn (task/draw.js's drawTask)
 * @property {import('../edit/rules.js').EditRules | null} edit   how the points may move (edit/rules.js): snapping,
 *   typed coordinates, points held on a line, on a plane or fixed
 */

const KEYS = [
  'ruledlab',
  'version',
  'id',
  'title',
  'prompt',
  'scene',
  'params',
  'input',
  'camera',
  'change',
  'hide',
  'answers',
  'goal',
  'hints',
  'solution',
  'draw',
  'edit',
];

/** An exercise that cannot be read: its message says where and why (in English; `details` for the page's language). */
export class TaskError extends Error {
  /** @param {string} reason  i18n key (task.error.*) @param {Record<string, string | number>} args */
  constructor(reason, args = {}) {
    super(englishOf(reason, args));
    this.name = 'TaskError';
    this.code = 'invalid-task';
    this.details = { reason, args };
  }
}

/** The English sentences of the reasons (the page says them in its language from `details`). */
const ENGLISH = /** @type {Record<string, string>} */ ({
  'task.error.notJson': 'The exercise is not JSON: {detail}.',
  'task.error.tooLong': 'The exercise is longer than {max} characters.',
  'task.error.notExercise': 'This is not a ruledlab exercise (its "ruledlab" must be "exercise", its "version" 1).',
  'task.error.unknownKey': 'The exercise has a key it does not know: "{key}" (in {where}).',
  'task.error.missing': 'The exercise lacks "{key}".',
  'task.error.type': '"{key}" must be {what}.',
  'task.error.text': '"{key}" must be a text of at most {max} characters.',
  'task.error.number': '"{key}" must be a finite number of magnitude at most {max}.',
  'task.error.count': '"{key}" may have at most {max} entries.',
  'task.error.condition': 'Condition {index} of the goal: {problem}',
  'task.error.id': '"id" must be 1 to {max} lowercase letters, digits and dashes.',
  'task.error.unknownBuiltIn': 'There is no built-in exercise "{id}".',
  'task.error.unknownScene': 'The exercise names a scene that does not exist: "{scene}".',
  'task.error.unknownParam': 'The scene "{scene}" has no parameter "{key}" (in {where}).',
  'task.error.badParam': 'The value of "{key}" (in {where}) is not one the scene takes.',
  'task.error.badInput': 'The edited input in "{where}" does not fit the scene.',
  'task.error.noHandles': 'The scene "{scene}" has no points to move, so "handles" cannot be changed.',
  'task.error.unknownValue': 'The scene computes no value "{value}" (named in {where}).',
  'task.error.noExact': 'The scene "{scene}" has no exact curve to compare a typed formula with.',
  'task.error.draw':
    '"draw.{name}" must be {"from", "to"} with from ≤ to and a positive "step" (at most {max} values), or {"list": [...]} of 1 to {most} numbers.',
  'task.error.notDrawn': '"{name}" (in {where}) is not a number the exercise draws.',
  'task.error.drawnParam': 'The drawn value {value} of "{key}" is not one the scene takes.',
  'task.error.seed': 'The seed must be a whole number from 0 to {max}.',
  'task.error.badLink': 'The link does not hold an exercise.',
  'task.check.noAnswer': 'No answer yet.',
});

function englishOf(/** @type {string} */ reason, /** @type {Record<string, string | number>} */ args) {
  return (ENGLISH[reason] ?? reason).replace(/\{(\w+)\}/g, (m, k) => (k in args ? String(args[k]) : m));
}

const isObject = (/** @type {unknown} */ x) => typeof x === 'object' && x !== null && !Array.isArray(x);

/** A text without control characters (a text is shown as text: nothing in it is markup). */
function text(/** @type {unknown} */ x, /** @type {string} */ key, max = MAX_TASK_TEXT) {
  if (typeof x !== 'string' || x.length > max) throw new TaskError('task.error.text', { key, max });
  // biome-ignore lint/suspicious/noControlCharactersInRegex: the control characters are what is removed
  return x.replace(/[\u0000-\u0008\u000b-\u001f\u007f]/g, '').trim();
}

/** Words: { en, de? }. */
function words(/** @type {unknown} */ x, /** @type {string} */ key, max = MAX_TASK_TEXT) {
  if (!isObject(x)) throw new TaskError('task.error.type', { key, what: 'an object { "en": …, "de": … }' });
  const o = /** @type {Record<string, unknown>} */ (x);
  for (const k of Object.keys(o))
    if (k !== 'en' && k !== 'de') throw new TaskError('task.error.unknownKey', { key: k, where: key });
  if (!('en' in o) && !('de' in o)) throw new TaskError('task.error.missing', { key: `${key}.en` });
  /** @type {Words} */
  const out = {};
  if ('en' in o) out.en = text(o.en, `${key}.en`, max);
  if ('de' in o) out.de = text(o.de, `${key}.de`, max);
  return out;
}

/** A finite number of sensible size. */
function number(/** @type {unknown} */ x, /** @type {string} */ key) {
  if (typeof x !== 'number' || !Number.isFinite(x) || Math.abs(x) > MAX_TASK_NUMBER)
    throw new TaskError('task.error.number', { key, max: LARGEST_NUMBER });
  return x;
}

/** A list of at most `max` entries. */
function list(/** @type {unknown} */ x, /** @type {string} */ key, /** @type {number} */ max) {
  if (!Array.isArray(x)) throw new TaskError('task.error.type', { key, what: 'a list' });
  if (x.length > max) throw new TaskError('task.error.count', { key, max });
  return x;
}

/** A name: a parameter key, a readout key, a measure's name, an answer's id. */
function name(/** @type {unknown} */ x, /** @type {string} */ key) {
  if (typeof x !== 'string' || !NAME.test(x))
    throw new TaskError('task.error.type', { key, what: 'a name of letters, digits, dots and dashes' });
  return x;
}

/**
 * The parameter values of a state: numbers, texts (a formula), switches, and numbers drawn
 * (`{ "drawn": name }`, where `draws` has them).
 * @returns {Record<string, number | string | boolean | {drawn: string}>}
 */
function params(/** @type {unknown} */ x, /** @type {string} */ key, /** @type {Record<string, Draw>} */ draws = {}) {
  if (!isObject(x)) throw new TaskError('task.error.type', { key, what: 'an object of parameter values' });
  /** @type {Record<string, number | string | boolean | {drawn: string}>} */
  const out = {};
  const entries = Object.entries(/** @type {Record<string, unknown>} */ (x));
  if (entries.length > MAX_TASK_NAMES) throw new TaskError('task.error.count', { key, max: MAX_TASK_NAMES });
  for (const [k, v] of entries) {
    name(k, `${key}`);
    if (typeof v === 'number') out[k] = number(v, `${key}.${k}`);
    else if (typeof v === 'boolean') out[k] = v;
    else if (isObject(v)) out[k] = drawnRef(v, `${key}.${k}`, draws);
    else out[k] = text(v, `${key}.${k}`, MAX_TEXT_PARAM);
  }
  return out;
}

/** `{ "drawn": name }`, naming a number of `draws`. */
function drawnRef(/** @type {unknown} */ x, /** @type {string} */ where, /** @type {Record<string, Draw>} */ draws) {
  const o = /** @type {Record<string, unknown>} */ (x);
  for (const k of Object.keys(o)) if (k !== 'drawn') throw new TaskError('task.error.unknownKey', { key: k, where });
  const n = name(o.drawn, `${where}.drawn`);
  if (!Object.keys(draws).includes(n)) throw new TaskError('task.error.notDrawn', { name: n, where });
  return { drawn: n };
}

/** The numbers drawn per attempt: { name: { from, to, step? } | { list } }. */
function readDraws(/** @type {unknown} */ x) {
  if (x === undefined) return {};
  if (!isObject(x)) throw new TaskError('task.error.type', { key: 'draw', what: 'an object of numbers drawn' });
  const entries = Object.entries(/** @type {Record<string, unknown>} */ (x));
  if (entries.length > MAX_TASK_DRAWS) throw new TaskError('task.error.count', { key: 'draw', max: MAX_TASK_DRAWS });
  /** @type {Record<string, Draw>} */
  const out = {};
  for (const [k, v] of entries) {
    name(k, 'draw');
    const fail = () =>
      new TaskError('task.error.draw', { name: k, max: MAX_DRAW_CHOICES.toLocaleString('en'), most: MAX_DRAW_LIST });
    if (!isObject(v)) throw fail();
    const o = /** @type {Record<string, unknown>} */ (v);
    const keys = Object.keys(o);
    if ('list' in o) {
      if (keys.length !== 1 || !Array.isArray(o.list) || !o.list.length || o.list.length > MAX_DRAW_LIST) throw fail();
      out[k] = {
        list: o.list.map((e, i) =>
          typeof e === 'number' ? number(e, `draw.${k}.list[${i}]`) : text(e, `draw.${k}.list[${i}]`, MAX_TASK_NAME),
        ),
      };
      continue;
    }
    if (keys.some((key) => !['from', 'to', 'step'].includes(key)) || !('from' in o) || !('to' in o)) throw fail();
    const from = number(o.from, `draw.${k}.from`);
    const to = number(o.to, `draw.${k}.to`);
    const step = o.step === undefined ? 1 : number(o.step, `draw.${k}.step`);
    if (!(step > 0) || from > to || (to - from) / step + 1 > MAX_DRAW_CHOICES) throw fail();
    out[k] = { from, to, step };
  }
  return out;
}

/**
 * A seed as a link or an element's attribute writes it (null: none given), and the note that says
 * it is not one (then a new one is drawn): "note.badSeed" or, for an element, "element.note.badSeed".
 * @param {string | null | undefined} text
 * @param {'note' | 'element.note'} [prefix]
 * @returns {{seed: number | null, note: {key: string, note: string, vars: Record<string, string>} | null}}
 */
export function linkSeed(text, prefix = 'note') {
  if (text === null || text === undefined) return { seed: null, note: null };
  try {
    return { seed: readSeed(text), note: null };
  } catch {
    return { seed: null, note: { key: 'task', note: `${prefix}.badSeed`, vars: { max: String(MAX_SEED) } } };
  }
}

/** A seed of the drawn numbers as a link or a course system gives it (a text or a number); throws a TaskError. */
export function readSeed(/** @type {unknown} */ x) {
  const t = typeof x === 'number' ? String(x) : typeof x === 'string' ? x.trim() : '';
  const n = /^\d{1,10}$/.test(t) ? Number(t) : Number.NaN;
  if (!(n <= MAX_SEED)) throw new TaskError('task.error.seed', { max: MAX_SEED });
  return n;
}

/** A number condition's bound: a number, { value } or { drawn }. */
function bound(/** @type {unknown} */ x, /** @type {string} */ key, /** @type {Record<string, Draw>} */ draws) {
  if (isObject(x)) {
    const o = /** @type {Record<string, unknown>} */ (x);
    if ('drawn' in o) return drawnRef(o, key, draws);
    for (const k of Object.keys(o))
      if (k !== 'value') throw new TaskError('task.error.unknownKey', { key: k, where: key });
    return { value: name(o.value, `${key}.value`) };
  }
  return number(x, key);
}

/** One condition of the goal. */
function condition(
  /** @type {unknown} */ x,
  /** @type {number} */ index,
  /** @type {Answer[]} */ answers,
  /** @type {Record<string, Draw>} */ draws,
) {
  const fail = (/** @type {string} */ problem) => new TaskError('task.error.condition', { index: index + 1, problem });
  if (!isObject(x)) throw fail('it must be an object');
  const o = /** @type {Record<string, unknown>} */ (x);
  const allowed = ['value', 'answer', 'below', 'above', 'near', 'within', 'matches', 'samples'];
  for (const k of Object.keys(o)) if (!allowed.includes(k)) throw fail(`unknown key "${k}"`);
  if ('value' in o === 'answer' in o) throw fail('it names either a "value" or an "answer"');
  /** @type {Condition} */
  const c = {};
  if ('value' in o) c.value = name(o.value, `goal[${index}].value`);
  if ('answer' in o) {
    c.answer = name(o.answer, `goal[${index}].answer`);
    if (!answers.some((a) => a.id === c.answer)) throw fail(`there is no answer "${c.answer}"`);
  }
  const tests = ['below', 'above', 'near', 'matches'].filter((k) => k in o);
  if (tests.length !== 1) throw fail('it has exactly one of "below", "above", "near" or "matches"');
  if ('below' in o) c.below = bound(o.below, `goal[${index}].below`, draws);
  if ('above' in o) c.above = bound(o.above, `goal[${index}].above`, draws);
  if ('near' in o) {
    c.near = bound(o.near, `goal[${index}].near`, draws);
    if (!('within' in o)) throw fail('"near" needs "within"');
  }
  if ('within' in o) {
    c.within = number(o.within, `goal[${index}].within`);
    if (c.within < 0) throw fail('"within" must not be negative');
  }
  if ('matches' in o) {
    if (o.matches !== 'striction' && o.matches !== 'distribution')
      throw fail('"matches" is "striction" (a curve s(u)) or "distribution" (a function δ(u))');
    c.matches = o.matches;
    const answer = answers.find((a) => a.id === c.answer);
    if (!answer || answer.kind !== (c.matches === 'striction' ? 'curve' : 'function'))
      throw fail(
        `"matches": "${c.matches}" is a condition on an answer of kind "${c.matches === 'striction' ? 'curve' : 'function'}"`,
      );
    if (!('within' in o)) throw fail('"matches" needs "within"');
    if ('samples' in o) {
      const n = number(o.samples, `goal[${index}].samples`);
      if (!Number.isInteger(n) || n < 2 || n > MAX_TASK_SAMPLES)
        throw fail(`"samples" is a whole number from 2 to ${MAX_TASK_SAMPLES}`);
      c.samples = n;
    }
  } else if ('samples' in o) throw fail('"samples" goes with "matches"');
  if (c.answer && !c.matches && answers.find((a) => a.id === c.answer)?.kind !== 'number')
    throw fail('a formula answer is checked with "matches"');
  if (c.value && c.matches) throw fail('"matches" is about an answer');
  return c;
}

/** The answers of a solution: numbers, or formulas (one text, or three). */
function solutionAnswers(/** @type {unknown} */ x, /** @type {Answer[]} */ answers) {
  if (!isObject(x)) throw new TaskError('task.error.type', { key: 'solution.answers', what: 'an object' });
  /** @type {Record<string, number | string | string[] | {value: string}>} */
  const out = {};
  for (const [k, v] of Object.entries(/** @type {Record<string, unknown>} */ (x))) {
    const answer = answers.find((a) => a.id === k);
    if (!answer) throw new TaskError('task.error.unknownKey', { key: k, where: 'solution.answers' });
    const key = `solution.answers.${k}`;
    if (answer.kind === 'number' && isObject(v)) {
      const o = /** @type {Record<string, unknown>} */ (v);
      for (const n of Object.keys(o))
        if (n !== 'value') throw new TaskError('task.error.unknownKey', { key: n, where: key });
      out[k] = { value: name(o.value, `${key}.value`) };
    } else if (answer.kind === 'number') out[k] = number(v, key);
    else if (answer.kind === 'function') out[k] = text(v, key, MAX_TEXT_PARAM);
    else out[k] = list(v, key, 3).map((t, i) => text(t, `${key}[${i}]`, MAX_TEXT_PARAM));
  }
  return out;
}

/**
 * Reads an exercise: a JSON text or the parsed object. Throws a TaskError (code
 * "invalid-task") saying what is wrong.
 * @param {unknown} source
 * @returns {Task}
 */
export function readTask(source) {
  let x = source;
  if (typeof source === 'string') {
    if (source.length > MAX_TASK) throw new TaskError('task.error.tooLong', { max: MAX_TASK });
    try {
      x = JSON.parse(source);
    } catch (e) {
      throw new TaskError('task.error.notJson', {
        detail: String(/** @type {Error} */ (e).message).slice(0, MAX_TASK_DETAIL),
      });
    }
  }
  if (!isObject(x)) throw new TaskError('task.error.notExercise');
  const o = /** @type {Record<string, unknown>} */ (x);
  if (o.ruledlab !== 'exercise' || o.version !== 1) throw new TaskError('task.error.notExercise');
  for (const k of Object.keys(o))
    if (!KEYS.includes(k)) throw new TaskError('task.error.unknownKey', { key: k, where: 'the exercise' });
  for (const k of ['id', 'title', 'prompt', 'scene', 'goal'])
    if (!(k in o)) throw new TaskError('task.error.missing', { key: k });
  if (typeof o.id !== 'string' || !ID.test(o.id)) throw new TaskError('task.error.id', { max: MAX_TASK_ID });
  const answers = list(o.answers ?? [], 'answers', MAX_TASK_ANSWERS).map((a, i) => {
    const key = `answers[${i}]`;
    if (!isObject(a)) throw new TaskError('task.error.type', { key, what: 'an object { id, kind, label }' });
    const r = /** @type {Record<string, unknown>} */ (a);
    for (const k of Object.keys(r))
      if (!['id', 'kind', 'label'].includes(k)) throw new TaskError('task.error.unknownKey', { key: k, where: key });
    if (r.kind !== 'number' && r.kind !== 'function' && r.kind !== 'curve')
      throw new TaskError('task.error.type', { key: `${key}.kind`, what: '"number", "function" or "curve"' });
    return /** @type {Answer} */ ({
      id: name(r.id, `${key}.id`),
      kind: r.kind,
      label: words(r.label, `${key}.label`, MAX_TASK_TITLE),
    });
  });
  if (new Set(answers.map((a) => a.id)).size !== answers.length)
    throw new TaskError('task.error.type', { key: 'answers', what: 'answers with different ids' });
  const draws = readDraws(o.draw);
  const goal = list(o.goal, 'goal', MAX_TASK_GOAL).map((c, i) => condition(c, i, answers, draws));
  if (!goal.length) throw new TaskError('task.error.missing', { key: 'goal[0]' });
  const names = (/** @type {unknown} */ v, /** @type {string} */ key) =>
    list(v ?? [], key, MAX_TASK_NAMES).map((n, i) => name(n, `${key}[${i}]`));
  let solution = null;
  if (o.solution !== undefined) {
    if (!isObject(o.solution)) throw new TaskError('task.error.type', { key: 'solution', what: 'an object' });
    const s = /** @type {Record<string, unknown>} */ (o.solution);
    for (const k of Object.keys(s))
      if (!['params', 'input', 'answers'].includes(k))
        throw new TaskError('task.error.unknownKey', { key: k, where: 'solution' });
    solution = {
      ...(s.params !== undefined
        ? { params: /** @type {Record<string, number | string | boolean>} */ (params(s.params, 'solution.params')) }
        : {}),
      ...(s.input !== undefined ? { input: text(s.input, 'solution.input', MAX_TASK_INPUT) } : {}),
      ...(s.answers !== undefined ? { answers: solutionAnswers(s.answers, answers) } : {}),
    };
  }
  // a drawn parameter holds the first value it can take until the exercise is drawn (task/draw.js)
  /** @type {Record<string, number | string | boolean>} */
  const start = {};
  /** @type {Record<string, string>} */
  const drawnParams = {};
  for (const [k, v] of Object.entries(o.params === undefined ? {} : params(o.params, 'params', draws))) {
    if (typeof v !== 'object') start[k] = v;
    else {
      drawnParams[k] = v.drawn;
      const d = draws[v.drawn];
      start[k] = 'list' in d ? d.list[0] : d.from;
    }
  }
  return {
    id: o.id,
    title: words(o.title, 'title', MAX_TASK_TITLE),
    prompt: words(o.prompt, 'prompt'),
    scene: name(o.scene, 'scene'),
    params: start,
    drawnParams,
    input: o.input === undefined ? null : text(o.input, 'input', MAX_TASK_INPUT),
    camera: o.camera === undefined ? null : text(o.camera, 'camera', MAX_TASK_CAMERA),
    change: names(o.change, 'change'),
    hide: names(o.hide, 'hide'),
    answers,
    goal,
    hints: list(o.hints ?? [], 'hints', MAX_TASK_HINTS).map((h, i) => words(h, `hints[${i}]`)),
    solution,
    draw: draws,
    drawn: null,
    edit:
      o.edit === undefined
        ? null
        : readEditRules(o.edit, (key, what) => {
            throw new TaskError('task.error.type', { key, what });
          }),
  };
}

/** The exercise as JSON (what readTask reads back to the same Task); a drawn one as it was written. */
export function writeTask(/** @type {Task} */ task) {
  const { input, camera, solution, draw, drawn: _, drawnParams, params, edit, ...rest } = task.drawn?.from ?? task;
  const written = {
    ...params,
    ...Object.fromEntries(Object.entries(drawnParams ?? {}).map(([k, n]) => [k, { drawn: n }])),
  };
  return JSON.stringify({
    ruledlab: 'exercise',
    version: 1,
    ...rest,
    params: written,
    ...(input ? { input } : {}),
    ...(camera ? { camera } : {}),
    ...(solution ? { solution } : {}),
    ...(Object.keys(draw ?? {}).length ? { draw } : {}),
    ...(edit ? { edit } : {}),
  });
}

/**
 * Words in `lang`, else in the language there is, their subscripts shown as everywhere on the page
 * ("m_i" → "mᵢ", "R_{i,i+1}" → "Rᵢ,ᵢ₊₁"; a caret stays as typed, for the formulas hints quote).
 */
export function say(/** @type {Words} */ w, /** @type {string} */ lang) {
  return plainSubscripts((lang === 'de' ? (w.de ?? w.en) : (w.en ?? w.de)) ?? '');
}

// —— in a link: a built-in exercise by its id, another as "j." and its JSON in base64url ——

/** The link value of an exercise: a built-in one's id, else its JSON, encoded. */
export function taskLink(/** @type {Task} */ task, /** @type {(id: string) => boolean} */ builtIn) {
  if (builtIn(task.id)) return task.id;
  return `j.${toBase64url(new TextEncoder().encode(writeTask(task)))}`;
}

/**
 * The exercise of a link value, read and checked (a built-in id, or "j." and base64url JSON);
 * throws a TaskError.
 * @param {string} value
 * @param {(id: string) => Task | null} builtIn
 */
export function taskFromLink(value, builtIn) {
  if (!value.startsWith('j.')) {
    const task = builtIn(value);
    if (!task) throw new TaskError('task.error.unknownBuiltIn', { id: value.slice(0, MAX_TASK_ID) });
    return task;
  }
  const text = value.slice(2);
  const bytes = text.length > (MAX_TASK * 4) / 3 + 4 ? null : fromBase64url(text);
  if (!bytes) throw new TaskError('task.error.badLink');
  let json = '';
  try {
    json = new TextDecoder('utf-8', { fatal: true }).decode(bytes);
  } catch {
    throw new TaskError('task.error.badLink');
  }
  return readTask(json);
}
