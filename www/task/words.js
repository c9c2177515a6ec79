// An exercise's conditions and their outcomes in the reader's words: what a condition asks
// ("the largest distance of the striction polygon from the exact curve below 0.001") and how it
// stands ("now 0.0023: it misses by 0.0013"). An answer's own value is never said (that would
// give it away): a typed curve says how far it is from the exact one and where.
import { say } from './format.js';
import { plainRich } from '../ui/richtext.js';
import { describeError } from '../ui/errors.js';
import { superscript } from '../i18n/translate.js';
import { ANSWER_CLOSE } from '../limits.js';

/**
 * @typedef {import('./format.js').Task} Task
 * @typedef {import('./format.js').Condition} Condition
 * @typedef {import('./check.js').Outcome} Outcome
 * @typedef {import('../i18n/index.js').Translator} Translator
 */

/** The name of a value a condition names: its readout's label, or the measure's own. */
export function valueName(/** @type {string} */ key, /** @type {Translator} */ { t, has }) {
  return plainRich(has(`measure.${key}`) ? t(`measure.${key}`) : t(key));
}

/**
 * A number an exercise states (a bound, a tolerance) as its author wrote it: "0.01", "10⁻⁹",
 * "2·10⁻⁴" (German "0,01"), not rounded to a readout's digits.
 */
export function statedNumber(/** @type {number} */ x, /** @type {string} */ lang) {
  const a = Math.abs(x);
  if (a === 0 || (a >= 1e-4 && a < 1e6))
    return x.toLocaleString(lang, { maximumSignificantDigits: 6, useGrouping: false }).replace('-', '−');
  const [m, e] = x.toExponential().split('e');
  const mantissa = Number(m);
  const power = `10${superscript(Number(e))}`;
  if (Math.abs(mantissa) === 1) return `${mantissa < 0 ? '−' : ''}${power}`;
  return `${mantissa.toLocaleString(lang, { maximumSignificantDigits: 6 }).replace('-', '−')}·${power}`;
}

/** The bound of a condition in words: a number, another value's name, or the name of a number drawn. */
function boundText(/** @type {import('./format.js').Bound} */ b, /** @type {Translator} */ i18n) {
  if (typeof b === 'number') return statedNumber(b, i18n.lang);
  return 'value' in b ? valueName(b.value, i18n) : `{${b.drawn}}`;
}

/** What a condition asks, in words. */
export function describeCondition(
  /** @type {Condition} */ c,
  /** @type {Task} */ task,
  /** @type {Translator} */ i18n,
) {
  const { t } = i18n;
  if (c.answer) {
    const answer = task.answers.find((a) => a.id === c.answer);
    const label = answer ? say(answer.label, i18n.lang) : c.answer;
    if (c.matches)
      return t(c.matches === 'striction' ? 'task.cond.matchesStriction' : 'task.cond.matchesDistribution', {
        answer: label,
        within: statedNumber(/** @type {number} */ (c.within), i18n.lang),
      });
    return t('task.cond.answer', { answer: label });
  }
  const name = valueName(/** @type {string} */ (c.value), i18n);
  if (c.below !== undefined) return t('task.cond.below', { name, bound: boundText(c.below, i18n) });
  if (c.above !== undefined) return t('task.cond.above', { name, bound: boundText(c.above, i18n) });
  return t('task.cond.near', {
    name,
    bound: boundText(/** @type {import('./format.js').Bound} */ (c.near), i18n),
    within: statedNumber(/** @type {number} */ (c.within), i18n.lang),
  });
}

/**
 * The field a typed answer's error is in, as the panel labels it: "δ(u)", or "s(u), z" for the
 * third formula of a curve (the core names them "delta[0]", "s[2]").
 */
function answerField(/** @type {Outcome} */ o, /** @type {Task | undefined} */ task, /** @type {Translator} */ i18n) {
  const answer = task?.answers.find((a) => a.id === o.condition.answer);
  if (!answer) return undefined;
  const label = say(answer.label, i18n.lang);
  const k = Number(/\[(\d)\]$/.exec(String(/** @type {any} */ (o.error)?.details?.option ?? ''))?.[1]);
  return answer.kind === 'curve' && k >= 0 && k < 3 ? `${label}, ${'xyz'[k]}` : label;
}

/** How a condition stands, in words (after its description). */
export function outcomeText(
  /** @type {Outcome} */ o,
  /** @type {Translator} */ i18n,
  /** @type {Task | undefined} */ task = undefined,
) {
  const { t, format } = i18n;
  const error = /** @type {any} */ (o.error);
  if (error) {
    const reason = error.details?.reason;
    if (reason === 'task.check.noAnswer') return t('task.out.noAnswer');
    const field = reason?.startsWith?.('task.') ? undefined : answerField(o, task, i18n);
    return t('task.out.error', { message: taskErrorText(error, i18n, field) });
  }
  const c = o.condition;
  if (c.answer && !c.matches) {
    if (o.holds) return t('task.out.right');
    // which way it misses, and whether it is close — never by how much (that would give the answer)
    if (!o.side) return t('task.out.notRight');
    const close = Math.abs(o.value - o.target) <= ANSWER_CLOSE * Math.abs(o.target);
    return t(`task.out.${o.side > 0 ? 'tooLarge' : 'tooSmall'}${close ? 'Close' : ''}`, {
      share: format(ANSWER_CLOSE * 100),
    });
  }
  if (!Number.isFinite(o.value)) return t('task.out.undefined');
  if (c.matches) {
    if (o.value === Number.POSITIVE_INFINITY) return t('task.out.curveUndefined', { at: format(o.at ?? Number.NaN) });
    return t(o.holds ? 'task.out.curveHolds' : 'task.out.curveMisses', {
      value: format(o.value),
      at: format(o.at ?? Number.NaN),
    });
  }
  if (o.holds) return t('task.out.holds', { value: format(o.value) });
  return t(o.side < 0 ? 'task.out.missesLow' : 'task.out.missesHigh', { value: format(o.value), miss: format(o.miss) });
}

/**
 * An exercise's error in the reader's words, to go inside a sentence: its own reasons
 * (task.error.*) from the language's texts, the core's (a typed formula refused) as the page
 * says them.
 * @param {unknown} error
 * @param {Translator} i18n
 * @param {string} [field]   the field it is in, as the reader sees it (a typed answer's label)
 */
export function taskErrorText(error, i18n, field) {
  const e = /** @type {any} */ (error);
  const reason = e?.details?.reason;
  if (typeof reason === 'string' && reason.startsWith('task.') && i18n.has(reason))
    return i18n.t(reason, e.details.args ?? {});
  return describeError(error, i18n, field);
}
