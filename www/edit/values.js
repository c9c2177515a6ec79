// Values where the hand is: while a handle moves, the quantities of its neighbourhood follow
// beside it — for a ruling's end φ, h and δ of both pairs it belongs to and δ̄ at its ruling, for
// a tool pose its orientation step and deviation (Editable.values: the scene reads them from what
// the core computed) — and, in an exercise, the value each condition checks, with its goal and
// whether it holds. A value the exercise hides is not shown: only whether the drag brings it
// closer to its goal or further from it.
import { checkGoal } from '../task/check.js';
import { valueName, statedNumber } from '../task/words.js';
import { valueText } from '../ui/readout.js';

/**
 * One line beside the handle.
 * @typedef {object} LiveLine
 * @property {string} label   rich text (`_{…}` subscripts)
 * @property {string} text    the value and, for an exercise's condition, its goal
 * @property {boolean} [holds]   an exercise's condition: whether it holds now
 */

export class LiveValues {
  /** @param {import('./editor.js').Editor} editor */
  constructor(editor) {
    this.editor = editor;
    /** @type {Map<number, number>} by condition: how far it missed when the move began */
    this.baseline = new Map();
  }

  /** The exercise's conditions on values, and how each stands on what is shown now. */
  outcomes() {
    const { hooks } = this.editor;
    const task = hooks.task?.();
    const built = hooks.built?.();
    if (!task || !built) return [];
    const goal = task.goal.filter((c) => c.value !== undefined);
    if (!goal.length) return [];
    const { outcomes } = checkGoal({ ...task, goal }, built, {}, /** @type {any} */ (null));
    return outcomes.map((o, i) => ({ o, hidden: task.hide.includes(/** @type {string} */ (o.condition.value)), i }));
  }

  /**
   * The exercise's conditions on the figure in words, said when a move ends ("every condition on
   * the figure holds: Check to confirm"), or "" without an exercise or conditions on values.
   */
  summary() {
    const outs = this.outcomes();
    if (!outs.length) return '';
    const met = outs.filter(({ o }) => o.holds).length;
    return this.editor.hooks
      .i18n()
      .t(met === outs.length ? 'value.allHold' : 'value.someHold', { met, of: outs.length });
  }

  /** A move begins: how far each condition misses now, for "closer" and "further". */
  begin() {
    this.baseline = new Map(this.outcomes().map(({ o, i }) => [i, o.miss]));
  }

  /**
   * What is shown beside handle `k`: its neighbourhood's values (the scene's), then the
   * exercise's conditions.
   * @param {number} k
   * @returns {LiveLine[]}
   */
  lines(k) {
    const editor = this.editor;
    const i18n = editor.hooks.i18n();
    const handle = editor.handles()[k];
    const built = editor.hooks.built?.();
    /** @type {LiveLine[]} */
    const out = [];
    const values = handle && built?.input?.values?.(handle.set, handle.index);
    for (const v of values ?? []) out.push({ label: i18n.t(v.label), text: valueText(v.value, v.exactZero, i18n) });
    const task = editor.hooks.task?.();
    if (!task) return out;
    for (const { o, hidden, i } of this.outcomes()) {
      const label = valueName(/** @type {string} */ (o.condition.value), i18n);
      if (hidden) {
        const before = this.baseline.get(i);
        const word =
          before === undefined || !Number.isFinite(o.miss) || !Number.isFinite(before) || o.miss === before
            ? 'value.same'
            : o.miss < before
              ? 'value.closer'
              : 'value.further';
        out.push({ label, text: i18n.t(o.holds ? 'value.holds' : word), holds: o.holds });
        continue;
      }
      const c = o.condition;
      const bound = c.below ?? c.above ?? c.near;
      // a drawn bound is a number once the attempt's numbers are drawn (task/draw.js)
      const target =
        typeof bound === 'number'
          ? statedNumber(bound, i18n.lang)
          : bound && 'value' in bound
            ? valueName(bound.value, i18n)
            : '';
      const goal = i18n.t(
        c.below !== undefined ? 'value.below' : c.above !== undefined ? 'value.above' : 'value.near',
        {
          bound: target,
        },
      );
      out.push({ label, text: `${valueText(o.value, true, i18n)} (${goal})`, holds: o.holds });
    }
    return out;
  }
}
