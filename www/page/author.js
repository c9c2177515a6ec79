// Writing an exercise without writing JSON: from the view on screen (Share → "Make an exercise"),
// a panel in the stage lets the lecturer pick what the reader may change and what is hidden,
// build the goal from the values the scene computes (each with its value now), type the title,
// the prompt and up to three hints, record the start and the solution from the view as she sets
// it, and take the link, iframe and element snippets (each with a Copy button), the JSON, or a
// SCORM package or an H5P file. Answers the reader types (a number, δ(u), s(u)) are written from
// the values and curves the scene knows (page/author-parts.js); a parameter may be drawn per
// attempt ("{n}" in the texts says it). Each condition shows whether it holds at the start and
// in the solution, and warnings say — for every number drawn, with the values — where the start
// already does what the goal says or the solution does not (page/author-warnings.js).
import { readTask, writeTask } from '../task/format.js';
import { measuresOf } from '../task/check.js';
import { describeCondition, statedNumber, valueName } from '../task/words.js';
import { encodeInput } from '../edit/input.js';
import { MAX_TASK_HINTS, MAX_TASK_SLUG, MAX_TASK_TEXT, MAX_TASK_TITLE, TASK_SAMPLES } from '../limits.js';
import { copyField } from './copy-field.js';
import { packageButtons, remember } from './packages.js';
import { answersBox, drawFields, slug } from './author-parts.js';
import { authorWarnings, outcomesAt, valueRanges } from './author-warnings.js';
import { drawTask } from '../task/draw.js';

/**
 * @typedef {import('../task/format.js').Task} Task
 *
 * What the author panel needs of the page.
 * @typedef {object} AuthorHooks
 * @property {() => import('../i18n/index.js').Translator} i18n
 * @property {() => import('../stage.js').Stage} stage
 * @property {(task: Task) => Promise<{link: string | null, iframe: string | null, element: string}>} snippets
 *   the Share dialog's snippets of an exercise (no link or iframe where the page has no address)
 * @property {(task: Task) => void} tryIt   opens the exercise as a reader sees it
 * @property {() => import('./packages.js').PackageSource} source   where a package's page files come from
 */

/**
 * @typedef {object} Row   one condition being written
 * @property {string} value
 * @property {'below' | 'above' | 'near'} test
 * @property {string} bound
 * @property {string} within
 */

/** Author panel states: what is recorded, per scene. */
export class Author {
  /**
   * @param {HTMLElement} box   its place in the stage's panel
   * @param {AuthorHooks} hooks
   */
  constructor(box, hooks) {
    this.box = box;
    this.hooks = hooks;
    this.open = false;
    /** @type {{params: import('../scene.js').Params, input: string | null} | null} */
    this.start = null;
    /** @type {{params: import('../scene.js').Params, input: string | null} | null} */
    this.solution = null;
    /** @type {Record<string, 'fixed' | 'change' | 'hide' | 'draw'>} */
    this.params = {};
    /** @type {Record<string, import('./author-parts.js').DrawRow>} parameters drawn per attempt */
    this.draws = {};
    /** @type {import('./author-parts.js').AnswerRow[]} answers the reader types */
    this.answers = [];
    this.handles = false;
    /** @type {Set<string>} readouts hidden */
    this.hidden = new Set();
    /** @type {Row[]} */
    this.rows = [];
    this.title = '';
    this.prompt = '';
    this.hints = Array(MAX_TASK_HINTS).fill('');
    /** @type {string} the scene the panel was opened on */
    this.scene = '';
  }

  /** Opens the panel on the view as it is (the start recorded from it). */
  show() {
    const stage = this.hooks.stage();
    if (!stage.scene) return;
    if (!this.open || this.scene !== stage.scene.id) {
      this.scene = stage.scene.id;
      this.params = Object.fromEntries(stage.scene.params.map((p) => [p.key, 'fixed']));
      this.draws = {};
      this.answers = [];
      this.handles = false;
      this.hidden = new Set();
      this.rows = [];
      this.solution = null;
      this.title = '';
      this.prompt = '';
      this.hints = Array(MAX_TASK_HINTS).fill('');
    }
    this.open = true;
    this.start = this.snapshot();
    this.render();
    /** @type {HTMLElement | null} */ (this.box.querySelector('input, textarea'))?.focus();
  }

  /** Closes the panel. */
  close() {
    this.open = false;
    this.box.hidden = true;
    this.box.replaceChildren();
  }

  /** @internal The view's state: its parameters and edit. */
  snapshot() {
    const stage = this.hooks.stage();
    return { params: { ...stage.params }, input: stage.input ? encodeInput(stage.input) : null };
  }

  /** The exercise as written so far (may throw a TaskError: what is missing). */
  task() {
    const stage = this.hooks.stage();
    const scene = /** @type {import('../scene.js').Scene} */ (stage.scene);
    const lang = this.hooks.i18n().lang === 'de' ? 'de' : 'en';
    const words = (/** @type {string} */ text) => ({ [lang]: text });
    const start = /** @type {NonNullable<Author['start']>} */ (this.start);
    // the start's parameters (all: what the reader may not change is held at these values)
    const params = Object.fromEntries(scene.params.map((p) => [p.key, start.params[p.key]]));
    const solutionParams = this.solution
      ? Object.fromEntries(
          scene.params
            .filter((p) => this.solution?.params[p.key] !== start.params[p.key])
            .map((p) => [p.key, this.solution?.params[p.key]]),
        )
      : null;
    const id = `${slug(this.title, MAX_TASK_SLUG) || 'exercise'}-${hash(
      JSON.stringify([params, start.input, this.rows, this.answers, this.draws]),
    )}`;
    // parameters drawn per attempt: their range, and { drawn } where the start holds them
    const drawn = Object.keys(this.params).filter((k) => this.params[k] === 'draw');
    for (const k of drawn) params[k] = /** @type {any} */ ({ drawn: k });
    const answers = this.answers.map((a, k) => ({ id: `answer${k + 1}`, kind: a.kind, label: words(a.label.trim()) }));
    /** @type {Record<string, unknown>} */
    const solutionAnswers = {};
    this.answers.forEach((a, k) => {
      const typed = a.solution.map((x) => x.trim());
      if (a.kind === 'number') {
        if (a.target) solutionAnswers[`answer${k + 1}`] = { value: a.target };
        else if (typed[0]) solutionAnswers[`answer${k + 1}`] = number(typed[0]);
      } else if (typed.every(Boolean)) solutionAnswers[`answer${k + 1}`] = a.kind === 'curve' ? typed : typed[0];
    });
    const hasSolution = this.solution || Object.keys(solutionAnswers).length;
    return readTask({
      ruledlab: 'exercise',
      version: 1,
      id,
      title: words(this.title.trim()),
      prompt: words(this.prompt.trim()),
      scene: scene.id,
      params,
      ...(start.input ? { input: start.input } : {}),
      change: [
        ...Object.entries(this.params)
          .filter(([, v]) => v === 'change')
          .map(([k]) => k),
        ...(this.handles ? ['handles'] : []),
      ],
      hide: [
        ...Object.entries(this.params)
          .filter(([, v]) => v === 'hide')
          .map(([k]) => k),
        ...this.hidden,
      ],
      ...(answers.length ? { answers } : {}),
      ...(drawn.length
        ? {
            draw: Object.fromEntries(
              drawn.map((k) => {
                const d = this.draws[k] ?? { from: '', to: '', step: '' };
                return [k, { from: number(d.from), to: number(d.to), step: d.step.trim() ? number(d.step) : 1 }];
              }),
            ),
          }
        : {}),
      goal: [
        ...this.rows.map((r) => ({
          value: r.value,
          [r.test]: number(r.bound),
          ...(r.test === 'near' ? { within: number(r.within) } : {}),
        })),
        ...this.answers.map((a, k) => {
          const answer = `answer${k + 1}`;
          const samples = a.samples.trim() ? { samples: number(a.samples) } : {};
          if (a.kind === 'number')
            return { answer, near: a.target ? { value: a.target } : number(a.bound), within: number(a.within) };
          return {
            answer,
            matches: a.kind === 'curve' ? 'striction' : 'distribution',
            within: number(a.within),
            ...samples,
          };
        }),
      ],
      hints: this.hints.filter((h) => h.trim()).map((h) => words(h.trim())),
      ...(hasSolution
        ? {
            solution: {
              ...(solutionParams && Object.keys(solutionParams).length ? { params: solutionParams } : {}),
              ...(this.solution && this.solution.input !== start.input && this.solution.input
                ? { input: this.solution.input }
                : {}),
              ...(Object.keys(solutionAnswers).length ? { answers: solutionAnswers } : {}),
            },
          }
        : {}),
    });
  }

  /** @internal The solution's typed answers, as the warnings check them. */
  solutionAnswers(/** @type {Task} */ task) {
    /** @type {import('./author-warnings.js').SolutionAnswers} */
    const out = {};
    for (const [k, v] of Object.entries(task.solution?.answers ?? {}))
      out[k] = Array.isArray(v) ? v : typeof v === 'object' ? v : String(v);
    return out;
  }

  /** @internal Whether each condition of `task` holds in a recorded state (computed by the scene). */
  holdsIn(
    /** @type {Task} */ task,
    /** @type {{params: import('../scene.js').Params, input: string | null}} */ state,
    /** @type {import('./author-warnings.js').SolutionAnswers} */ answers = {},
  ) {
    const stage = this.hooks.stage();
    const scene = /** @type {import('../scene.js').Scene} */ (stage.scene);
    const outcomes = outcomesAt(task, state, scene, stage.context(), answers);
    return outcomes ? outcomes.map((o) => o.holds) : task.goal.map(() => false);
  }

  /**
   * Builds the panel in the current language, the keyboard staying on the control it was on
   * (a change rebuilds the panel: ArrowDown in a menu, a bound typed, a state recorded). A text
   * field being typed in is never rebuilt: the field itself is kept in its place, with what was
   * typed into it meanwhile, its caret and its selection (a rebuild after Tab would otherwise
   * drop the selection Tab made, and the next keys would be added to the old value).
   */
  render() {
    const root = /** @type {Document | ShadowRoot} */ (this.box.getRootNode());
    const active = /** @type {HTMLElement | null} */ (root.activeElement);
    const name = active && this.box.contains(active) ? active.getAttribute('name') : null;
    const typing =
      name &&
      active &&
      (active.tagName === 'TEXTAREA' ||
        (active.tagName === 'INPUT' && /** @type {HTMLInputElement} */ (active).type === 'text'))
        ? /** @type {HTMLInputElement | HTMLTextAreaElement} */ (active)
        : null;
    const caret = typing
      ? /** @type {const} */ ([typing.selectionStart, typing.selectionEnd, typing.selectionDirection])
      : null;
    const scroll = this.box.scrollTop;
    this.build();
    if (!name) return;
    const find = (/** @type {string} */ n) =>
      /** @type {HTMLElement | null} */ (this.box.querySelector(`[name="${n}"]`));
    const fresh = find(name);
    if (typing && caret && fresh && fresh.tagName === typing.tagName) {
      // (its listeners write into the same state as the fresh field's would: the rows, draws and answers are kept objects)
      fresh.replaceWith(typing);
      typing.focus({ preventScroll: true });
      typing.setSelectionRange(caret[0], caret[1], /** @type {'forward' | 'backward' | 'none'} */ (caret[2] ?? 'none'));
      this.box.scrollTop = scroll;
      return;
    }
    const gone = name.startsWith('author-remove-')
      ? find('author-add')
      : name.startsWith('author-answer-remove-')
        ? find('author-answer-add')
        : null;
    (fresh ?? gone)?.focus({ preventScroll: true });
    this.box.scrollTop = scroll;
  }

  /** @internal */
  build() {
    if (!this.open) return;
    const stage = this.hooks.stage();
    const scene = stage.scene;
    if (!scene) return;
    const i18n = this.hooks.i18n();
    const { t } = i18n;
    const doc = this.box.ownerDocument;
    const el = (/** @type {string} */ tag, /** @type {Record<string, any>} */ props = {}) =>
      Object.assign(doc.createElement(tag), props);
    const field = (/** @type {string} */ label, /** @type {HTMLElement} */ input) => {
      const row = el('label', { className: 'rl-author-field' });
      row.append(el('span', { textContent: label }), input);
      return row;
    };
    this.box.hidden = false;
    const heading = el('h3', { textContent: t('author.heading'), id: 'rl-author-title' });
    this.box.setAttribute('aria-labelledby', heading.id);
    const intro = el('p', { className: 'rl-author-intro', textContent: t('author.intro') });
    const title = el('input', { type: 'text', value: this.title, maxLength: MAX_TASK_TITLE, name: 'author-title' });
    title.addEventListener('input', () => (this.title = title.value));
    const prompt = el('textarea', { rows: 4, value: this.prompt, maxLength: MAX_TASK_TEXT, name: 'author-prompt' });
    prompt.addEventListener('input', () => (this.prompt = prompt.value));

    // what the reader may change, and what is hidden
    const controls = el('fieldset', { className: 'rl-author-params' });
    controls.append(el('legend', { textContent: t('author.params') }));
    for (const p of scene.params) {
      const select = /** @type {HTMLSelectElement} */ (el('select', { name: `author-${p.key}` }));
      // (a number may be drawn per attempt, from a range)
      for (const v of ['fixed', 'change', 'hide', ...(p.type === 'range' ? ['draw'] : [])])
        select.add(new Option(t(`author.param.${v}`), v));
      select.value = this.params[p.key] ?? 'fixed';
      select.addEventListener('change', () => {
        this.params[p.key] = /** @type {'fixed' | 'change' | 'hide' | 'draw'} */ (select.value);
        if (select.value === 'draw') {
          const now = Number(stage.params[p.key]);
          this.draws[p.key] ??= {
            from: String(Math.max(Number(p.min), now - 4 * Number(p.step ?? 1))),
            to: String(Math.min(Number(p.max), now + 4 * Number(p.step ?? 1))),
            step: String(p.step ?? 1),
          };
          this.render();
        } else if (this.draws[p.key]) this.render();
      });
      controls.append(field(valueName(p.label, i18n), select));
      if (this.params[p.key] === 'draw')
        controls.append(
          drawFields({
            key: p.key,
            row: /** @type {any} */ (this.draws[p.key]),
            i18n,
            el,
            render: () => this.render(),
          }),
        );
    }
    if (stage.editor.sets.length) {
      const handles = el('input', { type: 'checkbox', checked: this.handles, name: 'author-handles' });
      handles.addEventListener('change', () => (this.handles = handles.checked));
      const row = el('label', { className: 'rl-author-check' });
      row.append(handles, ` ${t('author.handles')}`);
      controls.append(row);
    }
    const built = stage.session.built;
    const readouts = (built?.readouts ?? []).map((r) => r.label);
    const hide = el('fieldset', { className: 'rl-author-hide' });
    hide.append(el('legend', { textContent: t('author.hide') }));
    // the readouts, and the sentences that may say an answer: the claims under the readout, the explanation
    const hideable = [
      ...readouts.map((key) => [key, valueName(key, i18n)]),
      ...(built?.claims?.length ? [['claims', t('author.hide.claims')]] : []),
      ['text', t('author.hide.text')],
    ];
    for (const [key, label] of hideable) {
      const box = el('input', { type: 'checkbox', checked: this.hidden.has(key), name: `author-hide-${key}` });
      box.addEventListener('change', () => (box.checked ? this.hidden.add(key) : this.hidden.delete(key)));
      const row = el('label', { className: 'rl-author-check' });
      row.append(box, ` ${label}`);
      hide.append(row);
    }

    // the goal: conditions on the values the scene computes, each with its value now — or, where
    // the exercise draws numbers, the least and greatest it takes over the numbers that can be drawn
    const values = measuresOf(built);
    const ranges = this.start ? valueRanges(scene, stage.context(), this.start, this.params, this.draws) : null;
    const preview = (/** @type {string} */ key) => {
      const r = ranges?.[key];
      return r
        ? t('author.overDraws', { min: i18n.format(r.min), max: i18n.format(r.max) })
        : t('author.now', { value: i18n.format(values[key]) });
    };
    const goal = el('fieldset', { className: 'rl-author-goal' });
    goal.append(el('legend', { textContent: t('author.goal') }));
    let task = /** @type {Task | null} */ (null);
    let problem = '';
    try {
      task = this.rows.length || this.answers.length ? this.task() : null;
    } catch (e) {
      problem = String(/** @type {any} */ (e).message);
    }
    // (a drawn exercise: its conditions as they stand for the first numbers it draws)
    const first = task && Object.keys(task.draw).length ? drawsFirst(task) : task;
    const solutionState = this.solution ?? (task?.solution?.answers ? this.start : null);
    const atStart = first && this.start ? this.holdsIn(first, this.start) : [];
    const atSolution = first && solutionState ? this.holdsIn(first, solutionState, this.solutionAnswers(first)) : [];
    this.rows.forEach((r, k) => {
      const row = el('div', { className: 'rl-author-row' });
      const value = /** @type {HTMLSelectElement} */ (el('select', { name: `author-value-${k}` }));
      value.setAttribute('aria-label', t('author.value'));
      for (const key of Object.keys(values)) value.add(new Option(`${valueName(key, i18n)} (${preview(key)})`, key));
      value.value = r.value;
      value.addEventListener('change', () => {
        r.value = value.value;
        this.render();
      });
      const test = /** @type {HTMLSelectElement} */ (el('select', { name: `author-test-${k}` }));
      test.setAttribute('aria-label', t('author.test'));
      for (const v of ['below', 'above', 'near']) test.add(new Option(t(`author.test.${v}`), v));
      test.value = r.test;
      test.addEventListener('change', () => {
        r.test = /** @type {Row['test']} */ (test.value);
        this.render();
      });
      const bound = el('input', { type: 'text', inputMode: 'decimal', value: r.bound, name: `author-bound-${k}` });
      bound.setAttribute('aria-label', t('author.bound'));
      // (a field's change fires as Tab leaves it: the panel is rebuilt after the focus has moved on)
      bound.addEventListener('change', () => {
        r.bound = bound.value;
        setTimeout(() => this.render());
      });
      row.append(value, test, bound);
      if (r.test === 'near') {
        const within = el('input', { type: 'text', inputMode: 'decimal', value: r.within, name: `author-within-${k}` });
        within.setAttribute('aria-label', t('author.within'));
        within.addEventListener('change', () => {
          r.within = within.value;
          setTimeout(() => this.render());
        });
        row.append(el('span', { textContent: t('author.withinLabel') }), within);
      }
      const remove = el('button', { type: 'button', textContent: '×', name: `author-remove-${k}` });
      remove.setAttribute('aria-label', t('author.remove', { index: k + 1 }));
      remove.addEventListener('click', () => {
        this.rows.splice(k, 1);
        this.render();
      });
      row.append(remove);
      if (first) {
        const c = first.goal[k];
        const status = el('p', { className: 'rl-author-status' });
        status.textContent = `${describeCondition(c, first, i18n)}: ${t(atStart[k] ? 'author.holdsAtStart' : 'author.failsAtStart')}${
          solutionState ? `; ${t(atSolution[k] ? 'author.holdsInSolution' : 'author.failsInSolution')}` : ''
        }`;
        row.append(status);
      }
      goal.append(row);
    });
    // the answers the reader types are conditions of the goal too (written below, under Answers)
    if (first)
      first.goal.slice(this.rows.length).forEach((c, j) => {
        const k = this.rows.length + j;
        goal.append(
          el('p', {
            className: 'rl-author-status rl-author-answer-status',
            textContent: `${describeCondition(c, first, i18n)}: ${t(atStart[k] ? 'author.holdsAtStart' : 'author.answerAtStart')}${
              solutionState ? `; ${t(atSolution[k] ? 'author.holdsInSolution' : 'author.failsInSolution')}` : ''
            }`,
          }),
        );
      });
    const add = el('button', {
      type: 'button',
      textContent: t('author.add'),
      name: 'author-add',
      disabled: !Object.keys(values).length,
    });
    add.addEventListener('click', () => {
      const key = Object.keys(values)[0];
      this.rows.push({ value: key, test: 'below', bound: statedNumber(values[key], 'en'), within: '0.001' });
      this.render();
      /** @type {HTMLElement | null} */ (
        this.box.querySelector(`[name="author-value-${this.rows.length - 1}"]`)
      )?.focus();
    });
    goal.append(add);
    // the answers the reader types: a number, δ(u) or s(u), from what the scene computes and knows
    const exactOf = (/** @type {'striction' | 'distribution'} */ kind) => {
      try {
        return !!scene.exact?.(stage.params, stage.context(), kind, TASK_SAMPLES);
      } catch {
        return false;
      }
    };
    const answers = answersBox({
      rows: this.answers,
      values,
      preview,
      exact: { function: exactOf('distribution'), curve: exactOf('striction') },
      i18n,
      el,
      render: () => this.render(),
    });
    // what the start and the solution do, for every number drawn (with the values)
    const warnings = el('div', { className: 'rl-author-warnings' });
    warnings.setAttribute('role', 'status');
    if (task && this.start) {
      const list = authorWarnings(
        task,
        { start: this.start, solution: solutionState, answers: this.solutionAnswers(task) },
        scene,
        stage.context(),
        i18n,
      );
      warnings.hidden = !list.length;
      warnings.append(
        el('h4', { textContent: t('author.warn.heading') }),
        ...list.map((w) => el('p', { className: `rl-author-warning rl-warn-${w.kind}`, textContent: `⚠ ${w.text}` })),
      );
    } else warnings.hidden = true;

    const hints = el('fieldset', { className: 'rl-author-hints' });
    hints.append(el('legend', { textContent: t('author.hints', { max: MAX_TASK_HINTS }) }));
    this.hints.forEach((h, k) => {
      const area = el('textarea', { rows: 2, value: h, maxLength: MAX_TASK_TEXT, name: `author-hint-${k}` });
      area.addEventListener('input', () => (this.hints[k] = area.value));
      hints.append(field(t('author.hint', { index: k + 1 }), area));
    });

    // start and solution, recorded from the view
    const states = el('div', { className: 'rl-author-states' });
    const recordStart = el('button', {
      type: 'button',
      textContent: t('author.recordStart'),
      name: 'author-record-start',
    });
    recordStart.addEventListener('click', () => {
      this.start = this.snapshot();
      this.render();
    });
    const recordSolution = el('button', {
      type: 'button',
      textContent: t('author.recordSolution'),
      name: 'author-record-solution',
    });
    recordSolution.addEventListener('click', () => {
      this.solution = this.snapshot();
      this.render();
    });
    states.append(
      el('p', { textContent: t('author.startRecorded') }),
      recordStart,
      el('p', { textContent: t(this.solution ? 'author.solutionRecorded' : 'author.noSolution') }),
      recordSolution,
    );

    // the result: the exercise's snippets, or what is missing
    const out = el('div', { className: 'rl-author-out' });
    const make = el('button', { type: 'button', className: 'rl-author-make', textContent: t('author.make') });
    const result = el('div', { className: 'rl-author-result' });
    make.addEventListener('click', () => {
      // the texts as typed now (read from the panel: the field kept while typing may be an older build's)
      this.title = /** @type {HTMLInputElement} */ (this.box.querySelector('[name="author-title"]') ?? title).value;
      this.prompt = /** @type {HTMLTextAreaElement} */ (
        this.box.querySelector('[name="author-prompt"]') ?? prompt
      ).value;
      result.replaceChildren();
      let made;
      try {
        made = this.task();
      } catch (e) {
        const error = /** @type {any} */ (e);
        const reason = error?.details?.reason;
        result.append(
          el('p', {
            className: 'rl-author-problem',
            role: 'alert',
            textContent: reason && i18n.has(reason) ? upper(t(reason, error.details.args)) : String(error?.message),
          }),
        );
        return;
      }
      this.hooks.snippets(made).then((snippets) => {
        const lines = [];
        const copy = (/** @type {string} */ label, /** @type {string} */ value, /** @type {string} */ id) =>
          copyField(doc, t, { label, id, value });
        if (snippets.link) lines.push(copy(t('share.link'), snippets.link, 'author-link'));
        if (snippets.iframe) lines.push(copy(t('share.iframe'), snippets.iframe, 'author-iframe'));
        lines.push(copy(t('share.element'), snippets.element, 'author-element'));
        lines.push(copy(t('author.json'), writeTask(made), 'author-json'));
        remember(made);
        const packages = packageButtons(
          doc,
          () => this.hooks.i18n(),
          () => [made],
          () => ({
            ...this.hooks.source(),
            lang: this.hooks.i18n().lang,
            readers: { controls: true, edit: true },
            title: made.title[this.hooks.i18n().lang === 'de' ? 'de' : 'en'] ?? '',
          }),
          'author',
        );
        const tryIt = el('button', { type: 'button', textContent: t('author.try') });
        tryIt.addEventListener('click', () => this.hooks.tryIt(made));
        result.append(...lines, packages, tryIt);
        /** @type {HTMLElement | null} */ (result.querySelector('textarea'))?.focus();
      });
    });
    const close = el('button', { type: 'button', textContent: t('author.close') });
    close.addEventListener('click', () => this.close());
    out.append(make, close, result);
    if (problem && (this.rows.length || this.answers.length))
      out.append(el('p', { className: 'rl-author-problem', textContent: problem }));
    this.box.replaceChildren(
      heading,
      intro,
      field(t('author.title'), title),
      field(t('author.prompt'), prompt),
      controls,
      hide,
      goal,
      answers,
      hints,
      states,
      warnings,
      out,
    );
  }
}

/** A drawn exercise with the numbers of seed 0 (how its conditions are shown while it is written). */
function drawsFirst(/** @type {Task} */ task) {
  return drawTask(task, 0);
}

/** A number as typed ("0,5" too); NaN when it is none (the format refuses it then). */
function number(/** @type {string} */ text) {
  const x = Number(String(text).trim().replace('−', '-').replace(',', '.'));
  return text.trim() === '' ? Number.NaN : x;
}

/** A short hash of a text, for an exercise's id. */
function hash(/** @type {string} */ text) {
  let h = 2166136261;
  for (let i = 0; i < text.length; i++) h = Math.imul(h ^ text.charCodeAt(i), 16777619);
  return (h >>> 0).toString(36);
}

const upper = (/** @type {string} */ s) => s.charAt(0).toUpperCase() + s.slice(1);
