// The exercise in the stage's panel: its title and prompt, the reader's answer fields, Check (each
// condition: holds or not, by how much it misses, in words; solved said in words and by a mark,
// not by colour alone), up to three hints revealed in turn, the solution on request (after as many
// checks as the lecturer allows, or never), Start over, and Leave; the numbers drawn for this
// attempt and the checks made so far (the attempt: task/attempt.js). A solution shown earns
// nothing: it is reported as a `solution`, not a check, and every check of the attempt after it
// is reported as not counted. All of it is text: an exercise's texts are never markup.
import { say } from './format.js';
import { checkGoal, measuresOf, unreadable } from './check.js';
import { describeCondition, outcomeText } from './words.js';
import { drawnText } from './draw.js';
import { MAX_TASK_HISTORY, TASK_HISTORY_SHOWN } from '../limits.js';

/**
 * @typedef {import('./format.js').Task} Task
 *
 * What the panel needs of its stage.
 * @typedef {object} TaskHooks
 * @property {() => import('../i18n/index.js').Translator} i18n
 * @property {() => {scene: import('../scene.js').Scene, params: import('../scene.js').Params, context: import('../scene.js').Context, built: import('../scene.js').Built} | null} state
 *   what is shown now (null while the scene cannot be computed)
 * @property {() => void} startOver      back to the exercise's start
 * @property {() => void} showSolution   the solution's state (parameters, edit)
 * @property {(() => void) | null} leave the page leaves the exercise (an element cannot)
 * @property {() => boolean} [mayLeave]  whether Leave is offered now (an embed hides it unless allowed)
 * @property {() => SolutionRule} [solutionRule]   when the solution is offered (default: after a first check)
 * @property {(type: 'check' | 'solved' | 'solution', detail: TaskReport) => void} report
 *
 * When the reader may have the solution shown: after `after` checks that did not solve the
 * exercise (1: after a first check), or never (null).
 * @typedef {{after: number | null}} SolutionRule
 *
 * What a check reports (the `task-check` and `task-solved` events, and a message to the page
 * around a frame); the solution shown reports the same (`task-solution`), with `counted` false.
 * @typedef {object} TaskReport
 * @property {string} task        the exercise's id
 * @property {string} title
 * @property {boolean} solved     solved by this check, and it counts (never with the solution shown)
 * @property {boolean} counted    whether it counts toward a score: false for the solution shown and
 *   every check after it in the same attempt (a grade takes nothing from it)
 * @property {boolean} shown      the solution has been shown in this attempt
 * @property {number} passed      how many conditions hold
 * @property {number} of          how many there are
 * @property {Array<{holds: boolean, value: number | null, target: number | null}>} conditions
 *   (an answer condition's value and target are null: they would give the answer away)
 * @property {import('./check.js').Answers} answers
 * @property {number | null} seed   the seed of the numbers drawn (null: the exercise draws none)
 * @property {Record<string, number | string> | null} drawn   the numbers drawn, by name
 *
 * One check of an attempt: when (ms since 1970), how many conditions held, of how many; `shown`:
 * the solution shown ('solution') or a check made after it ('after') — neither counts.
 * @typedef {{at: number, passed: number, of: number, shown?: 'solution' | 'after'}} Check
 *
 * What the reader has done in an exercise: her answers, the hints shown, her checks, whether she
 * has had the solution shown.
 * @typedef {object} PanelAttempt
 * @property {import('./check.js').Answers} answers
 * @property {number} hints
 * @property {Check[]} checks
 * @property {boolean} shown
 */

let serial = 0;

export class TaskPanel {
  /**
   * @param {HTMLElement} box   the panel's place in the stage
   * @param {TaskHooks} hooks
   */
  constructor(box, hooks) {
    this.box = box;
    this.hooks = hooks;
    /** @type {Task | null} */
    this.task = null;
    /** @type {import('./check.js').Answers} */
    this.answers = {};
    this.hints = 0;
    this.checked = false;
    this.solved = false;
    /** the solution has been shown in this attempt: nothing since counts */
    this.shown = false;
    /** @type {Check[]} */
    this.checks = [];
    this.id = `rl-task-${++serial}`;
  }

  /**
   * Shows an exercise (null: none): its answers empty and no hint shown, or as `attempt` left
   * them (answers, hints shown, checks made, the solution shown).
   * @param {Task | null} task
   * @param {Partial<PanelAttempt> | null} [attempt]
   */
  show(task, attempt = null) {
    this.task = task;
    this.answers = structuredClone(attempt?.answers ?? {});
    this.hints = Math.min(task?.hints.length ?? 0, attempt?.hints ?? 0);
    this.checks = [...(attempt?.checks ?? [])].slice(-MAX_TASK_HISTORY);
    this.shown = !!attempt?.shown || this.checks.some((c) => c.shown);
    this.checked = this.checks.length > 0;
    this.solved = this.checks.some((c) => !c.shown && c.passed === c.of);
    this.render();
  }

  /** What the reader has done so far (a copy). @returns {PanelAttempt} */
  attempt() {
    return {
      answers: structuredClone(this.answers),
      hints: this.hints,
      checks: this.checks.map((c) => ({ ...c })),
      shown: this.shown,
    };
  }

  /** Checks made so far that did not solve the exercise (and count). */
  failures() {
    return this.checks.filter((c) => !c.shown && c.passed < c.of).length;
  }

  /** Whether the solution is offered now: the exercise has one, the lecturer allows it, and enough checks failed. */
  solutionOffered() {
    const after = (this.hooks.solutionRule?.() ?? { after: 1 }).after;
    return !!this.task?.solution && after !== null && (this.shown || this.solved || this.failures() >= after);
  }

  /** Builds the panel in the current language (answers typed so far stay). */
  render() {
    const task = this.task;
    this.box.hidden = !task;
    if (!task) return this.box.replaceChildren();
    const i18n = this.hooks.i18n();
    const { t, lang } = i18n;
    const doc = this.box.ownerDocument;
    const el = (/** @type {string} */ tag, /** @type {Record<string, any>} */ props = {}) =>
      Object.assign(doc.createElement(tag), props);
    const heading = el('h3', { className: 'rl-task-title', id: `${this.id}-title` });
    heading.append(
      el('span', { className: 'rl-task-kind', textContent: `${t('task.heading')} ` }),
      say(task.title, lang),
    );
    this.box.setAttribute('aria-labelledby', heading.id);
    const prompt = el('p', { className: 'rl-task-prompt', textContent: say(task.prompt, lang) });
    const held = el('p', { className: 'rl-task-held', textContent: t(this.asks(task) ? 'task.held' : 'task.heldAll') });
    const answers = el('div', { className: 'rl-task-answers' });
    for (const a of task.answers) {
      const label = say(a.label, lang);
      if (a.kind === 'curve') {
        const group = el('fieldset', { className: 'rl-task-curve' });
        group.append(el('legend', { textContent: label }));
        const typed = /** @type {string[]} */ (Array.isArray(this.answers[a.id]) ? this.answers[a.id] : ['', '', '']);
        ['x', 'y', 'z'].forEach((c, k) => {
          const field = this.field(`${a.id}-${c}`, `${c}(u) =`, typed[k] ?? '', (v) => {
            const now = /** @type {string[]} */ (Array.isArray(this.answers[a.id]) ? this.answers[a.id] : ['', '', '']);
            now[k] = v;
            this.answers[a.id] = now;
          });
          group.append(field);
        });
        answers.append(group);
      } else {
        answers.append(
          this.field(
            a.id,
            a.kind === 'function' ? `${label} =` : label,
            String(this.answers[a.id] ?? ''),
            (v) => {
              this.answers[a.id] = v;
            },
            a.kind === 'number',
          ),
        );
      }
    }
    const buttons = el('div', { className: 'rl-task-buttons' });
    const check = el('button', { type: 'button', className: 'rl-task-check', textContent: t('task.check') });
    check.addEventListener('click', () => this.check());
    const hint = el('button', {
      type: 'button',
      className: 'rl-task-hint',
      textContent: t('task.hint', { shown: this.hints, count: task.hints.length }),
      disabled: this.hints >= task.hints.length,
      hidden: task.hints.length === 0,
    });
    hint.addEventListener('click', () => {
      this.hints = Math.min(task.hints.length, this.hints + 1);
      this.render();
      /** @type {HTMLElement | null} */ (this.box.querySelector(`.rl-task-hints li:nth-child(${this.hints})`))?.focus();
    });
    // the solution: where the exercise has one and the lecturer allows it, after enough checks
    const rule = this.hooks.solutionRule?.() ?? { after: 1 };
    const offered = this.solutionOffered();
    const solution = el('button', {
      type: 'button',
      className: 'rl-task-solution',
      textContent: t('task.solution'),
      hidden: !task.solution || rule.after === null,
      disabled: !offered,
      title: offered ? t('task.solutionCounts') : t('task.solutionAfter', { count: rule.after ?? 1 }),
    });
    solution.addEventListener('click', () => {
      this.solve();
      // (the panel is new: the keyboard stays on its button)
      /** @type {HTMLElement | null} */ (this.box.querySelector('.rl-task-solution'))?.focus();
    });
    const again = el('button', { type: 'button', className: 'rl-task-again', textContent: t('task.startOver') });
    again.addEventListener('click', () => {
      // the figure back to the start first, then the panel (the checks made so far stay: they are
      // the attempt's record); the verdict was of the figure before, so it waits for the next check
      this.hooks.startOver();
      this.show(task, { checks: this.checks, shown: this.shown });
      for (const part of this.box.querySelectorAll('.rl-task-results, .rl-task-verdict'))
        if (part instanceof HTMLElement) part.hidden = true;
      // (the panel is new: the keyboard stays on its Start over)
      /** @type {HTMLElement | null} */ (this.box.querySelector('.rl-task-again'))?.focus();
    });
    buttons.append(check, hint, solution, again);
    if (this.hooks.leave && (this.hooks.mayLeave?.() ?? true)) {
      const leave = el('button', { type: 'button', className: 'rl-task-leave', textContent: t('task.leave') });
      leave.addEventListener('click', () => this.hooks.leave?.());
      buttons.append(leave);
    }
    const hints = el('ol', { className: 'rl-task-hints', hidden: this.hints === 0 });
    hints.setAttribute('aria-label', t('task.hints'));
    task.hints.slice(0, this.hints).forEach((h) => {
      hints.append(el('li', { textContent: say(h, lang), tabIndex: -1 }));
    });
    const results = el('ul', { className: 'rl-task-results', hidden: true });
    results.setAttribute('aria-label', t('task.results'));
    const verdict = el('p', { className: 'rl-task-verdict', hidden: true });
    verdict.setAttribute('role', 'status');
    const drawn = drawnText(task, lang);
    const numbers = el('p', {
      className: 'rl-task-drawn',
      textContent: drawn ? t('task.drawn', { values: drawn }) : '',
      hidden: !drawn,
    });
    const history = el('div', { className: 'rl-task-history' });
    this.box.replaceChildren(heading, prompt, numbers, answers, buttons, hints, results, verdict, history, held);
    this.showChecks();
    if (this.checked) this.check(false, this.checks.at(-1)?.shown === 'solution' ? 'solution' : 'check');
  }

  /** The checks made so far, the latest first (a few; how many more there were). */
  showChecks() {
    const box = /** @type {HTMLElement | null} */ (this.box.querySelector('.rl-task-history'));
    if (!box) return;
    const { t, lang } = this.hooks.i18n();
    const doc = this.box.ownerDocument;
    box.hidden = this.checks.length === 0;
    if (box.hidden) return box.replaceChildren();
    const time = (/** @type {number} */ at) =>
      new Date(at).toLocaleTimeString(lang, { hour: '2-digit', minute: '2-digit', second: '2-digit' });
    const list = doc.createElement('ol');
    list.reversed = true;
    const shown = this.checks.slice(-TASK_HISTORY_SHOWN).reverse();
    list.start = this.checks.length;
    for (const c of shown)
      list.append(
        Object.assign(doc.createElement('li'), {
          textContent:
            c.shown === 'solution'
              ? t('task.historySolution', { time: time(c.at) })
              : c.shown
                ? t('task.historyAfter', { time: time(c.at), passed: c.passed, of: c.of })
                : c.passed === c.of
                  ? `✓ ${t('task.historySolved', { time: time(c.at) })}`
                  : t('task.historyEntry', { time: time(c.at), passed: c.passed, of: c.of }),
        }),
      );
    const heading = Object.assign(doc.createElement('h4'), { textContent: t('task.history') });
    const more = this.checks.length - shown.length;
    box.replaceChildren(heading, list);
    if (more > 0)
      box.append(Object.assign(doc.createElement('p'), { textContent: t('task.historyMore', { count: more }) }));
  }

  /**
   * The solution on screen, its answers filled in and its conditions shown (null where it is not
   * offered). It counts for nothing, and nothing checked after it in this attempt does: it is
   * reported as a `solution`, with the score of the checks before it untouched.
   */
  solve() {
    const task = this.task;
    if (!task?.solution || !this.solutionOffered()) return null;
    this.shown = true;
    this.hooks.showSolution();
    // a number the scene computes in the solution's state ({ value }) is read from what it built now
    const values = measuresOf(this.hooks.state()?.built ?? null);
    for (const [k, v] of Object.entries(task.solution.answers ?? {}))
      this.answers[k] = Array.isArray(v)
        ? [...v]
        : typeof v === 'object'
          ? String(Number((values[v.value] ?? Number.NaN).toPrecision(12)))
          : String(v);
    this.render();
    return this.check(true, 'solution');
  }

  /** Whether the exercise lets the reader change anything in the scene. */
  asks(/** @type {Task} */ task) {
    return task.change.length > 0;
  }

  /**
   * An answer field with its label.
   * @param {string} key @param {string} label @param {string} value
   * @param {(value: string) => void} onInput
   * @param {boolean} [number]
   */
  field(key, label, value, onInput, number = false) {
    const doc = this.box.ownerDocument;
    const row = Object.assign(doc.createElement('label'), { className: 'rl-task-field' });
    const input = Object.assign(doc.createElement('input'), {
      type: 'text',
      name: `task-${key}`,
      value,
      spellcheck: false,
      autocomplete: 'off',
      className: number ? 'rl-task-number' : 'rl-formula',
      // a number may be negative, a fraction or a power of ten (−1.711, 1/13, 2·10^-3): a phone's
      // decimal keypad (iOS's) has no minus, slash or caret, so every answer takes the keyboard
      inputMode: 'text',
    });
    // as the scene's own formula fields: no capital letter or correction of "sin(u)" or "2e-3"
    input.setAttribute('autocapitalize', 'off');
    input.setAttribute('autocorrect', 'off');
    input.addEventListener('input', () => onInput(input.value));
    // Enter in a field checks
    input.addEventListener('keydown', (e) => {
      if (e.key === 'Enter') {
        e.preventDefault();
        this.check();
      }
    });
    row.append(Object.assign(doc.createElement('span'), { textContent: label }), input);
    return row;
  }

  /**
   * Checks the goal on what is shown: each condition in words, solved or not; reports it
   * (`announce`: say it and keep it). `kind` 'solution': the solution shown, which counts for nothing.
   * @param {boolean} [announce]
   * @param {'check' | 'solution'} [kind]
   */
  check(announce = true, kind = 'check') {
    const task = this.task;
    if (!task) return null;
    const i18n = this.hooks.i18n();
    const { t } = i18n;
    const results = /** @type {HTMLElement} */ (this.box.querySelector('.rl-task-results'));
    const verdict = /** @type {HTMLElement} */ (this.box.querySelector('.rl-task-verdict'));
    const state = this.hooks.state();
    const doc = this.box.ownerDocument;
    this.checked = true;
    if (!state) {
      results.hidden = true;
      verdict.hidden = false;
      verdict.className = 'rl-task-verdict';
      verdict.textContent = t('task.noPicture');
      return null;
    }
    const { outcomes, solved: holds } = checkGoal(task, state.built, this.answers, state);
    /** whether a check that counts had solved it before this one (the first that does is reported as solved) */
    const before = this.solved;
    // (the solution shown, and every check after it, count for nothing)
    const counts = !this.shown;
    const solved = holds && counts;
    results.replaceChildren(
      ...outcomes.map((o) => {
        const li = doc.createElement('li');
        li.className = o.holds ? 'rl-holds' : 'rl-fails';
        const mark = Object.assign(doc.createElement('span'), {
          className: 'rl-mark',
          textContent: o.holds ? '✓' : '✗',
        });
        mark.setAttribute('aria-hidden', 'true');
        const status = Object.assign(doc.createElement('span'), {
          className: 'rl-sr-only',
          textContent: `${t(o.holds ? 'task.holds' : 'task.notYet')}: `,
        });
        const words = Object.assign(doc.createElement('span'), {
          textContent: `${describeCondition(o.condition, task, i18n)} — ${outcomeText(o, i18n, task)}`,
        });
        li.append(mark, status, words);
        return li;
      }),
    );
    results.hidden = false;
    verdict.hidden = false;
    verdict.className = solved ? 'rl-task-verdict rl-task-solved' : 'rl-task-verdict';
    const passed = outcomes.filter((o) => o.holds).length;
    // an answer that could not be read is said with how to write it, and the check is not counted
    const readable = !outcomes.some(unreadable);
    verdict.textContent =
      kind === 'solution'
        ? t('task.solutionShown')
        : !counts
          ? t(holds ? 'task.afterSolutionHolds' : 'task.afterSolution', { passed, of: outcomes.length })
          : solved
            ? `✓ ${t('task.solved')}`
            : readable
              ? t('task.notSolved', { passed, of: outcomes.length })
              : t('task.notCounted');
    /** @type {TaskReport} */
    const report = {
      task: task.id,
      title: task.title.en ?? task.title.de ?? task.id,
      solved,
      counted: counts,
      shown: this.shown,
      passed,
      of: outcomes.length,
      conditions: outcomes.map((o) => ({
        holds: o.holds,
        value: o.condition.answer && !o.condition.matches ? null : Number.isFinite(o.value) ? o.value : null,
        target: o.condition.answer && !o.condition.matches ? null : Number.isFinite(o.target) ? o.target : null,
      })),
      answers: structuredClone(this.answers),
      seed: task.drawn?.seed ?? null,
      drawn: task.drawn ? { ...task.drawn.values } : null,
    };
    if (announce && (readable || kind === 'solution')) {
      /** @type {Check} */
      const entry = { at: Date.now(), passed, of: outcomes.length };
      if (!counts) entry.shown = kind === 'solution' ? 'solution' : 'after';
      this.checks = [...this.checks, entry].slice(-MAX_TASK_HISTORY);
      this.showChecks();
    }
    // (a check not announced — the panel built anew — only shows how the figure stands)
    if (announce) this.solved = this.solved || solved;
    // the solution, once enough checks have failed (or at once, where the lecturer allows it)
    const offer = /** @type {HTMLButtonElement | null} */ (this.box.querySelector('.rl-task-solution'));
    if (offer) {
      const offered = this.solutionOffered();
      offer.disabled = !offered;
      const rule = this.hooks.solutionRule?.() ?? { after: 1 };
      offer.title = offered ? t('task.solutionCounts') : t('task.solutionAfter', { count: rule.after ?? 1 });
    }
    if (announce) {
      // where the panel runs below the screen (a phone), the verdict is brought into sight
      verdict.scrollIntoView({ block: 'nearest' });
      if (kind === 'solution') this.hooks.report('solution', report);
      else if (readable) this.hooks.report('check', report);
      if (solved && !before) this.hooks.report('solved', report);
    }
    return report;
  }
}
