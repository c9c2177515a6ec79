// What the exercise author checks before she hands an exercise out: its start must not already
// do what the goal says, and its recorded solution must — for every number it draws (the draws'
// values tried: each of a list, a range's ends and a few seeds between). Each warning says the
// condition, the numbers drawn where there are any, and the values the scene computes there.
import { checkGoal, measuresOf } from '../task/check.js';
import { describeCondition, outcomeText } from '../task/words.js';
import { drawChoices, drawTask, drawnText } from '../task/draw.js';
import { decodeInput } from '../edit/input.js';
import { withChoices } from '../scene.js';

/**
 * @typedef {import('../task/format.js').Task} Task
 * @typedef {{params: import('../scene.js').Params, input: string | null}} Recorded
 * @typedef {Record<string, string | string[] | {value: string}>} SolutionAnswers
 *
 * @typedef {object} Warning
 * @property {'start' | 'solution' | 'error'} kind   the start passes, the solution fails, or the scene cannot be computed there
 * @property {string} text   in the reader's language
 */

/** Seeds a drawn exercise is tried with: enough to meet each value of a short list or a range's ends. */
const SEEDS = 24;

/**
 * The exercises students can get: `task` itself, or — drawing numbers — one per distinct draw
 * among the first seeds.
 * @param {Task} task
 */
export function drawsToTry(task) {
  if (!Object.keys(task.draw).length) return [task];
  const seen = new Map();
  for (let seed = 0; seed < SEEDS; seed++) {
    const drawn = drawTask(task, seed);
    const key = JSON.stringify(drawn.drawn?.values);
    if (!seen.has(key)) seen.set(key, drawn);
  }
  // in the order of their numbers (n = 8, 9, …)
  const order = (/** @type {Task} */ t) => Object.values(t.drawn?.values ?? {});
  return [...seen.values()].sort((a, b) => {
    const [x, y] = [order(a), order(b)];
    for (let k = 0; k < x.length; k++)
      if (x[k] !== y[k])
        return typeof x[k] === 'number' ? Number(x[k]) - Number(y[k]) : String(x[k]).localeCompare(String(y[k]));
    return 0;
  });
}

/**
 * Checks `task` at a recorded state: each condition's outcome (null when the scene cannot be
 * computed there).
 * @param {Task} task   drawn (if it draws)
 * @param {Recorded} state   the start or the solution as recorded (a drawn parameter takes its drawn value)
 * @param {import('../scene.js').Scene} scene
 * @param {import('../scene.js').Context} context
 * @param {SolutionAnswers} answers   (a number the scene computes there: { value })
 */
export function outcomesAt(task, state, scene, context, answers) {
  const params = withChoices(scene, { ...state.params, ...drawnParams(task) });
  const input = state.input ? decodeInput(state.input) : null;
  const ctx = { ...context, input: input ?? undefined };
  try {
    const built = scene.create(params, ctx);
    const values = measuresOf(built);
    /** @type {import('../task/check.js').Answers} */
    const typed = {};
    for (const [k, v] of Object.entries(answers))
      typed[k] = Array.isArray(v) ? v : typeof v === 'object' ? String(values[v.value]) : v;
    return checkGoal(task, built, typed, { scene, params, context: ctx }).outcomes;
  } catch {
    return null;
  }
}

/** The parameters an exercise draws, at their drawn values. */
function drawnParams(/** @type {Task} */ task) {
  return Object.fromEntries(Object.keys(task.drawnParams).map((k) => [k, task.params[k]]));
}

/**
 * The warnings of an exercise being written (see the module's documentation).
 * @param {Task} task   as written (not drawn)
 * @param {{start: Recorded, solution: Recorded | null, answers: SolutionAnswers}} states   the start, the
 *   solution and its typed answers, as recorded
 * @param {import('../scene.js').Scene} scene
 * @param {import('../scene.js').Context} context
 * @param {import('../i18n/index.js').Translator} i18n
 * @returns {Warning[]}
 */
export function authorWarnings(task, states, scene, context, i18n) {
  const { t, format, lang } = i18n;
  /** the warnings by their text, each with the numbers drawn it holds for (said once, with all of them) */
  /** @type {Map<string, {kind: Warning['kind'], numbers: string[]}>} */
  const found = new Map();
  const warn = (/** @type {Warning['kind']} */ kind, /** @type {string} */ text, /** @type {string} */ numbers) => {
    const seen = found.get(text) ?? { kind, numbers: [] };
    if (numbers) seen.numbers.push(numbers);
    found.set(text, seen);
  };
  const value = (/** @type {import('../task/check.js').Outcome} */ o) =>
    Number.isFinite(o.value) ? format(o.value) : t('task.out.undefined');
  for (const drawn of drawsToTry(task)) {
    const numbers = drawnText(drawn, lang);
    const start = outcomesAt(drawn, states.start, scene, context, {});
    if (!start) warn('error', t('author.warn.startBroken'), numbers);
    else if (start.every((o) => o.holds))
      warn(
        'start',
        t('author.warn.startSolves', {
          values: start.map((o) => `${describeCondition(o.condition, drawn, i18n)}: ${value(o)}`).join('; '),
        }),
        numbers,
      );
    if (!states.solution) continue;
    const solved = outcomesAt(drawn, states.solution, scene, context, states.answers);
    if (!solved) {
      warn('error', t('author.warn.solutionBroken'), numbers);
      continue;
    }
    solved.forEach((o, k) => {
      if (o.holds) return;
      const text = t('author.warn.solutionFails', {
        index: k + 1,
        condition: describeCondition(o.condition, drawn, i18n),
        outcome: outcomeText(o, i18n, drawn),
      });
      warn('solution', text, numbers);
    });
  }
  return [...found].map(([text, { kind, numbers }]) => ({
    kind,
    text: `${numbers.length ? t('author.warn.with', { numbers: numbers.join('; ') }) : ''}${text}`,
  }));
}

/**
 * The least and greatest value of each number the scene computes, over the numbers an exercise
 * being written can draw (its drawn parameters' ranges as typed, with the start's other
 * parameters): what a goal's bound or an answer's target is compared with across the attempts.
 * Every combination when there are at most SEEDS of them, else SEEDS spread evenly over them
 * (the first and the last among them). Null when nothing is drawn or no range can be read.
 * @param {import('../scene.js').Scene} scene
 * @param {import('../scene.js').Context} context
 * @param {Recorded} start
 * @param {Record<string, string>} roles   each parameter's role ('draw': drawn per attempt)
 * @param {Record<string, {from: string, to: string, step: string}>} draws   the ranges as typed
 * @returns {Record<string, {min: number, max: number}> | null}
 */
export function valueRanges(scene, context, start, roles, draws) {
  const read = (/** @type {string} */ x) => Number(String(x).trim().replace('−', '-').replace(',', '.'));
  /** @type {Array<[string, number[]]>} */
  const axes = [];
  for (const [key, role] of Object.entries(roles)) {
    if (role !== 'draw' || !draws[key]) continue;
    const from = read(draws[key].from);
    const to = read(draws[key].to);
    const step = draws[key].step.trim() ? read(draws[key].step) : 1;
    if (!Number.isFinite(from) || !Number.isFinite(to) || !(step > 0) || to < from || (to - from) / step > 1e4)
      continue;
    axes.push([key, /** @type {number[]} */ (drawChoices({ from, to, step }))]);
  }
  if (!axes.length) return null;
  const total = axes.reduce((n, [, values]) => n * values.length, 1);
  const picks =
    total <= SEEDS
      ? [...Array(total).keys()]
      : [...Array(SEEDS).keys()].map((k) => Math.round((k * (total - 1)) / (SEEDS - 1)));
  const input = start.input ? decodeInput(start.input) : null;
  const ctx = { ...context, input: input ?? undefined };
  /** @type {Record<string, {min: number, max: number}>} */
  const out = {};
  for (let index of picks) {
    /** @type {Record<string, number>} */
    const combo = {};
    for (const [key, values] of axes) {
      combo[key] = values[index % values.length];
      index = Math.floor(index / values.length);
    }
    try {
      const values = measuresOf(scene.create(withChoices(scene, { ...start.params, ...combo }), ctx));
      for (const [key, v] of Object.entries(values)) {
        if (!Number.isFinite(v)) continue;
        const r = out[key] ?? { min: v, max: v };
        out[key] = { min: Math.min(r.min, v), max: Math.max(r.max, v) };
      }
    } catch {
      // (a combination the scene cannot compute: the warnings say it)
    }
  }
  return Object.keys(out).length ? out : null;
}
