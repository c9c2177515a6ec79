// Checking an exercise (task/format.js) against what the core computed: each condition of the
// goal, whether it holds, the value it is about and by how much it misses; and whether an
// exercise fits its scene at all (its parameters, the values its conditions name). The values
// are the scene's numeric readouts, by their keys, and its measures (Built.measures); a typed
// s(u) or δ(u) is evaluated by the core (evaluateFormulas) and compared with the exact curve the
// scene's analytic surface gives (Scene.exact).
import { evaluateFormulas } from '../../pkg/ruledlab.js';
import { readValue, serialize } from '../scene.js';
import { decodeInput, fitsSets } from '../edit/input.js';
import { HIDE_WORDS, TaskError } from './format.js';
import { TASK_SAMPLES, MAX_TASK_CHECKED_DRAWS } from '../limits.js';
import { drawChoices } from './draw.js';

/**
 * @typedef {import('./format.js').Task} Task
 * @typedef {import('./format.js').Condition} Condition
 *
 * What the reader typed: a number's text, a formula, or three formulas.
 * @typedef {Record<string, string | string[]>} Answers
 *
 * The outcome of one condition.
 * @typedef {object} Outcome
 * @property {Condition} condition
 * @property {boolean} holds
 * @property {number} value    the value it is about (for "matches": the largest distance found); NaN when there is none
 * @property {number} target   what it is compared with
 * @property {number} miss     by how much it misses (0 when it holds)
 * @property {-1 | 0 | 1} side  which way it misses: 1 too large, −1 too small (0 when it holds or there is no value)
 * @property {unknown} [error] why there is no value (an answer not given, a formula the core refused)
 * @property {number} [at]     "matches": where the typed formula is farthest from the exact one (u)
 */

/** The values conditions may name: every numeric readout by its key, and the scene's measures. */
export function measuresOf(/** @type {import('../scene.js').Built | null} */ built) {
  /** @type {Record<string, number>} */
  const values = {};
  for (const r of built?.readouts ?? []) if (typeof r.value === 'number') values[r.label] = r.value;
  Object.assign(values, built?.measures ?? {});
  return values;
}

/** Superscript digits and signs, as the readout writes a power of ten ("10⁻³"). */
const SUPERSCRIPTS = /** @type {Record<string, string>} */ ({
  '⁰': '0',
  '¹': '1',
  '²': '2',
  '³': '3',
  '⁴': '4',
  '⁵': '5',
  '⁶': '6',
  '⁷': '7',
  '⁸': '8',
  '⁹': '9',
  '⁻': '-',
  '⁺': '+',
});

/**
 * A number as a reader types it, or as the page writes it, in the page's language `lang`: "0.25"
 * and "0,25" (either decimal sign), "1/3", "−2", groups of three as the language writes them
 * ("250,000"; German "250.000"), and a power of ten as the readout writes it ("1.89·10⁻³",
 * "1,89·10⁻³", "1.89×10^-3", "1.89e-3"). NaN when it is not one.
 * @param {string} text @param {string} [lang]
 */
export function answerNumber(text, lang = 'en') {
  const t = String(text)
    .trim()
    .replace(/[\u2212\u2012\u2013]/g, '-')
    .replace(/[\s\u00a0\u202f\u2009]/g, '');
  const fraction = /^([+-]?[\d.,]+)\/([\d.,]+)$/.exec(t);
  if (fraction) return decimal(fraction[1], lang) / decimal(fraction[2], lang);
  const power = /^([+-]?[\d.,]+)(?:[·⋅×*x]10(?:\^|\*\*)?\(?([+-]?\d+|[⁺⁻]?[⁰¹²³⁴⁵⁶⁷⁸⁹]+)\)?)$/.exec(t);
  if (power) {
    const exponent = Number(power[2].replace(/[⁰¹²³⁴⁵⁶⁷⁸⁹⁺⁻]/g, (c) => SUPERSCRIPTS[c]));
    const mantissa = decimal(power[1], lang);
    return Number.isInteger(exponent) ? Number(`${mantissa}e${exponent}`) : Number.NaN;
  }
  return decimal(t, lang);
}

/** A decimal number in `lang`'s writing or with the other decimal sign, or with an exponent ("e-3"). */
function decimal(/** @type {string} */ text, /** @type {string} */ lang) {
  const [group, point] = lang === 'de' ? ['.', ','] : [',', '.'];
  const grouped = new RegExp(`^[+-]?\\d{1,3}(\\${group}\\d{3})+(\\${point}\\d*)?$`);
  const t = (grouped.test(text) ? text.split(group).join('') : text).replace(',', '.');
  return /^[+-]?(\d+\.?\d*|\.\d+)(e[+-]?\d+)?$/i.test(t) ? Number(t) : Number.NaN;
}

/**
 * Whether a condition could not be checked because an answer could not be read (a number that is
 * not one, a formula the core refused): the check is shown with how to write it, but it does not
 * count as an attempt.
 * @param {Outcome} outcome
 */
export function unreadable(outcome) {
  const e = /** @type {any} */ (outcome.error);
  return e?.details?.reason === 'task.check.notNumber' || e?.code === 'parse-error' || e?.code === 'too-large';
}

/**
 * Checks the goal of `task` on what the scene built (and the reader's answers).
 * @param {Task} task
 * @param {import('../scene.js').Built} built
 * @param {Answers} answers
 * @param {{scene: import('../scene.js').Scene, params: import('../scene.js').Params, context: import('../scene.js').Context}} state
 * @returns {{outcomes: Outcome[], solved: boolean}}
 */
export function checkGoal(task, built, answers, state) {
  const values = measuresOf(built);
  const of = (/** @type {import('./format.js').Bound} */ b) =>
    typeof b === 'number' ? b : 'value' in b ? (values[b.value] ?? Number.NaN) : Number.NaN;
  const outcomes = task.goal.map((condition) => {
    /** @type {Outcome} */
    const outcome = { condition, holds: false, value: Number.NaN, target: Number.NaN, miss: Number.NaN, side: 0 };
    try {
      if (condition.matches) return matches(outcome, answers, state);
      if (condition.value) outcome.value = values[condition.value] ?? Number.NaN;
      else {
        const typed = answers[/** @type {string} */ (condition.answer)];
        outcome.value = typeof typed === 'string' ? answerNumber(typed, state.context.lang) : Number.NaN;
        if (typed === undefined || String(typed).trim() === '') outcome.error = new TaskError('task.check.noAnswer');
        else if (Number.isNaN(outcome.value)) outcome.error = new TaskError('task.check.notNumber');
      }
      const x = outcome.value;
      if (condition.below !== undefined) {
        outcome.target = of(condition.below);
        outcome.holds = x < outcome.target;
        outcome.miss = outcome.holds ? 0 : x - outcome.target;
      } else if (condition.above !== undefined) {
        outcome.target = of(condition.above);
        outcome.holds = x > outcome.target;
        outcome.miss = outcome.holds ? 0 : outcome.target - x;
      } else if (condition.near !== undefined) {
        outcome.target = of(condition.near);
        const off = Math.abs(x - outcome.target);
        const within = /** @type {number} */ (condition.within);
        outcome.holds = off <= within;
        outcome.miss = outcome.holds ? 0 : off - within;
      }
      if (!outcome.holds)
        outcome.side =
          condition.below !== undefined ? 1 : condition.above !== undefined ? -1 : x > outcome.target ? 1 : -1;
    } catch (e) {
      outcome.error = e;
    }
    // a value that is not a number (NaN: undefined here) never satisfies a condition
    if (!Number.isFinite(outcome.value) || !Number.isFinite(outcome.target)) {
      outcome.holds = false;
      outcome.side = 0;
    }
    if (outcome.holds) outcome.side = 0;
    return outcome;
  });
  return { outcomes, solved: outcomes.every((o) => o.holds) };
}

/** A typed s(u) or δ(u) against the exact one, at the scene's parameters: the largest distance. */
function matches(
  /** @type {Outcome} */ outcome,
  /** @type {Answers} */ answers,
  /** @type {{scene: import('../scene.js').Scene, params: import('../scene.js').Params, context: import('../scene.js').Context}} */ state,
) {
  const c = outcome.condition;
  const id = /** @type {string} */ (c.answer);
  const typed = answers[id];
  const texts = Array.isArray(typed) ? typed : typeof typed === 'string' ? [typed] : [];
  outcome.target = /** @type {number} */ (c.within);
  if (!texts.length || texts.some((x) => !String(x).trim())) {
    outcome.error = new TaskError('task.check.noAnswer');
    return outcome;
  }
  const exact = state.scene.exact?.(
    state.params,
    state.context,
    /** @type {'striction' | 'distribution'} */ (c.matches),
    c.samples ?? TASK_SAMPLES,
  );
  if (!exact) throw new TaskError('task.error.noExact', { scene: state.scene.id });
  const width = c.matches === 'striction' ? 3 : 1;
  const p = state.params;
  const typedValues = evaluateFormulas(
    {
      formulas: texts.map(String),
      name: id,
      parameters: { a: Number(p.a ?? 1), b: Number(p.b ?? 1), c: Number(p.c ?? 1) },
      decimalComma: state.context.lang === 'de' ? true : 'unambiguous',
    },
    exact.u,
  );
  let worst = 0;
  let at = Number.NaN;
  for (let k = 0; k < exact.u.length; k++) {
    let d2 = 0;
    for (let i = 0; i < width; i++) {
      const d = typedValues[width * k + i] - exact.values[width * k + i];
      d2 += d * d;
    }
    // (a point where the exact curve is undefined, a cylindrical ruling, is not compared)
    if (exact.values.subarray(width * k, width * k + width).some(Number.isNaN)) continue;
    const d = Math.sqrt(d2);
    if (!(d <= worst)) [worst, at] = [Number.isNaN(d) ? Number.POSITIVE_INFINITY : d, exact.u[k]];
  }
  outcome.value = worst;
  outcome.at = at;
  outcome.holds = worst <= outcome.target;
  outcome.miss = outcome.holds ? 0 : worst - outcome.target;
  return outcome;
}

/**
 * Whether an exercise fits its scene: its parameters are the scene's and valid, what it lets
 * change or hides exists, its edit fits the scene's handles, and every value its conditions name
 * is one the scene computes (at the start or in the solution). Throws a TaskError.
 * @param {Task} task
 * @param {import('../scene.js').Scene[]} scenes
 * @param {(params: import('../scene.js').Params, input: import('../scene.js').Input | null) => import('../scene.js').Built} compute
 *   the scene computed at these parameters (and edit)
 */
export function fitTask(task, scenes, compute) {
  const scene = scenes.find((s) => s.id === task.scene);
  if (!scene) throw new TaskError('task.error.unknownScene', { scene: task.scene });
  const keys = scene.params.map((p) => p.key);
  const known = (/** @type {Record<string, unknown>} */ params, /** @type {string} */ where) => {
    for (const [k, v] of Object.entries(params)) {
      const p = scene.params.find((q) => q.key === k);
      if (!p) throw new TaskError('task.error.unknownParam', { key: k, where, scene: scene.id });
      const read = readValue(p, serialize(p, /** @type {number | string | boolean} */ (v)));
      if (read.note && p.type !== 'select') throw new TaskError('task.error.badParam', { key: k, where });
    }
  };
  // a drawn parameter: every value it can take must be one the scene takes (of a long range, its
  // ends), and a whole number where the control takes whole numbers (N rulings, steps)
  for (const [k, name] of Object.entries(task.drawnParams)) {
    const draw = task.draw[name];
    const p = scene.params.find((q) => q.key === k);
    const all = 'list' in draw ? draw.list : drawChoices(draw);
    const candidates = all.length <= MAX_TASK_CHECKED_DRAWS ? all : [all[0], all[all.length - 1]];
    const whole = p?.type === 'range' && Number.isInteger(p.step ?? 1) && Number.isInteger(p.min ?? 0);
    const wholeDraw = 'list' in draw || (Number.isInteger(draw.from) && Number.isInteger(draw.step));
    for (const value of whole && !wholeDraw
      ? [...candidates, draw.from + /** @type {any} */ (draw).step]
      : candidates) {
      const read = p ? readValue(p, serialize(p, value)) : null;
      if (!read || read.note || read.value !== value || (whole && !Number.isInteger(value)))
        throw new TaskError('task.error.drawnParam', { key: k, value: String(value) });
    }
  }
  known(task.params, 'params');
  if (task.solution?.params) known(task.solution.params, 'solution.params');
  for (const c of task.change)
    if (c !== 'handles' && !keys.includes(c))
      throw new TaskError('task.error.unknownParam', { key: c, where: 'change', scene: scene.id });
  const decode = (/** @type {string | null | undefined} */ text, /** @type {string} */ where) => {
    if (!text) return null;
    const input = decodeInput(text);
    if (!input) throw new TaskError('task.error.badInput', { where });
    return input;
  };
  const startInput = decode(task.input, 'input');
  const start = compute(task.params, null);
  if (startInput && !(start.input && fitsSets(startInput, start.input.sets)))
    throw new TaskError('task.error.badInput', { where: 'input' });
  if (task.change.includes('handles') && !start.input) throw new TaskError('task.error.noHandles', { scene: scene.id });
  const built = [compute(task.params, startInput)];
  if (task.solution) {
    const solutionInput = decode(task.solution.input, 'solution.input');
    built.push(compute({ ...task.params, ...(task.solution.params ?? {}) }, solutionInput));
  }
  const values = new Set(built.flatMap((b) => Object.keys(measuresOf(b))));
  // (a readout that is not a number, "0.01 / 0.02", can be hidden though no condition names it)
  const shown = new Set(built.flatMap((b) => (b.readouts ?? []).map((r) => r.label)));
  for (const h of task.hide)
    if (!keys.includes(h) && !values.has(h) && !shown.has(h) && !HIDE_WORDS.includes(h))
      throw new TaskError('task.error.unknownValue', { value: h, where: 'hide' });
  task.goal.forEach((c, i) => {
    const named = [
      c.value,
      ...[c.below, c.above, c.near].map((b) => (typeof b === 'object' && 'value' in b ? b.value : undefined)),
    ];
    for (const v of named)
      if (v !== undefined && !values.has(v))
        throw new TaskError('task.error.unknownValue', { value: v, where: `goal[${i}]` });
    if (c.matches && !scene.exact) throw new TaskError('task.error.noExact', { scene: scene.id });
  });
  for (const [k, a] of Object.entries(task.solution?.answers ?? {}))
    if (a && typeof a === 'object' && !Array.isArray(a) && !values.has(a.value))
      throw new TaskError('task.error.unknownValue', { value: a.value, where: `solution.answers.${k}` });
  return scene;
}
