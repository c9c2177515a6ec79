// A scene on screen with everything around it: the 3D view (labels, legend, toolbar with
// Fit / Reset / Fullscreen / shortcuts, progress, errors), and beside or below it — as the
// width allows — the controls with the player, the readout, the description, downloads and
// the explanation. The page (app.js) and <ruled-view> are both a Stage plus their own chrome;
// a Stage is told its state and reports every change, it never touches the URL itself.
import { start } from './core.js';
import { Viewer } from './viewer.js';
import { SceneSession } from './session.js';
import { defaults, withChoices } from './scene.js';
import { translator, pickLanguage } from './i18n/translate.js';
import { buildControls } from './ui/controls.js';
import { showLegend } from './ui/legend.js';
import { showReadout, showClaims, readoutSentence } from './ui/readout.js';
import { describeError } from './ui/errors.js';
import { Player } from './ui/player.js';
import { appendRich, plainRich } from './ui/richtext.js';
import { refineInWorker } from './compute.js';
import { atPreset } from './paper.js';
import { canFullscreen } from './platform.js';
import { NARROW, PORTRAIT, TINY, SMALL_VIEW } from './limits.js';
import { Editor } from './edit/editor.js';
import { copyInput, decodeInput, fitsSets, inputOf } from './edit/input.js';
import { TaskPanel } from './task/panel.js';
import { say } from './task/format.js';

/** Least time between two announcements of the readout (ms). */
const ANNOUNCE_EVERY = 1000;

/**
 * @typedef {object} StageOptions
 * @property {boolean} [controls]   show the controls (and the readout)
 * @property {boolean} [text]       show the explanation
 * @property {string | null} [lang]
 * @property {boolean} [page]       the stage is the page's (the page scrolls; a narrow view stays at the top of the screen)
 * @property {boolean} [editable]   the reader may drag the scene's handles (the page; <ruled-view editable>)
 * @property {(data: import('./scene.js').ImportedData) => void} [onEditAsData]   "Edit as data" of a
 *   scene without handles: show its sample as your data (the "data" scene)
 * @property {(change: {reason: 'scene' | 'param' | 'camera' | 'lang' | 'reset' | 'input', ended: boolean}) => void} [onChange]
 * @property {(type: 'check' | 'solved', report: import('./task/panel.js').TaskReport) => void} [onTask]
 *   an exercise was checked, or solved
 * @property {() => void} [onLeaveTask]   the reader leaves the exercise (the page; an element has no Leave)
 * @property {(error: unknown, message: string) => void} [onError]   with the sentence shown
 * @property {(built: import('./scene.js').Built) => void} [onBuilt]
 */

let serial = 0;

export class Stage {
  /**
   * @param {HTMLElement} host   the element the stage fills (or a container in a shadow root)
   * @param {StageOptions} [options]
   */
  constructor(host, options = {}) {
    /** @internal */
    this.host = host;
    /** @internal */
    this.options = options;
    /** @internal */
    this.i18n = translator(pickLanguage(options.lang));
    const id = `rl-stage-${++serial}`;
    const doc = host.ownerDocument;
    const el = (/** @type {string} */ tag, /** @type {Record<string, any>} */ props = {}) =>
      Object.assign(doc.createElement(tag), props);

    /** @internal */
    this.root = el('div', { className: options.page ? 'rl-stage rl-page' : 'rl-stage' });
    /** @internal */
    this.view = el('div', { className: 'rl-view' });
    /** @internal */
    this.canvas = /** @type {HTMLCanvasElement} */ (el('canvas', { tabIndex: 0 }));
    this.canvas.setAttribute('role', 'img');
    /** @internal */
    this.labels = el('div', { className: 'rl-labels' });
    this.labels.setAttribute('aria-hidden', 'true');
    /** @internal */
    this.legend = el('ul', { className: 'rl-legend' });
    /** @internal */
    this.toolbar = el('div', { className: 'rl-toolbar' });
    /** @internal */
    this.progress = el('div', { className: 'rl-progress', hidden: true });
    /** @internal */
    this.progressBar = el('progress', { max: 1, value: 0 });
    /** @internal */
    this.cancel = el('button', { type: 'button' });
    this.progress.append(this.progressBar, this.cancel);
    /** @internal */
    this.error = el('p', { className: 'rl-error', hidden: true });
    this.error.setAttribute('role', 'alert');
    /** @internal */
    this.noteBox = el('p', { className: 'rl-note', hidden: true });
    /** @internal */
    this.hint = el('p', { className: 'rl-hint' });
    /** @internal */
    this.description = el('p', { className: 'rl-sr-only', id: `${id}-description` });
    this.canvas.setAttribute('aria-describedby', this.description.id);
    /** @internal */
    this.status = el('p', { className: 'rl-sr-only' });
    this.status.setAttribute('aria-live', 'polite');
    // the hint and the toolbar share the bottom edge: the hint takes what room the buttons leave
    /** @internal */
    this.bar = el('div', { className: 'rl-bar' });
    // while editing (in the hint's place): how a drag moves a handle (for those without Shift and Alt), and Done
    /** @internal */
    this.editBar = el('div', { className: 'rl-editbar', hidden: true });
    /** @internal @type {Record<import('./edit/geometry.js').MoveMode, HTMLButtonElement>} */
    this.modes = {
      view: /** @type {HTMLButtonElement} */ (el('button', { type: 'button' })),
      line: /** @type {HTMLButtonElement} */ (el('button', { type: 'button' })),
      vertical: /** @type {HTMLButtonElement} */ (el('button', { type: 'button' })),
    };
    /** @internal */
    this.modeLabel = el('span', { className: 'rl-editbar-label' });
    /** @internal */
    this.done = el('button', { type: 'button', className: 'rl-done' });
    /** @internal */
    this.modeGroup = el('div', { className: 'rl-modes' });
    this.modeGroup.setAttribute('role', 'group');
    this.modeGroup.append(this.modeLabel, ...Object.values(this.modes));
    this.editBar.append(this.modeGroup, this.done);
    this.bar.append(this.hint, this.editBar, this.toolbar);
    this.view.append(
      this.canvas,
      this.labels,
      this.legend,
      this.bar,
      this.progress,
      this.noteBox,
      this.error,
      this.description,
      this.status,
    );

    /** @internal */
    this.buttons = {
      edit: el('button', { type: 'button', className: 'rl-edit', hidden: true }),
      undo: el('button', { type: 'button', className: 'rl-undo', hidden: true }),
      redo: el('button', { type: 'button', className: 'rl-redo', hidden: true }),
      fit: el('button', { type: 'button', className: 'rl-fit' }),
      reset: el('button', { type: 'button', className: 'rl-reset' }),
      fullscreen: el('button', { type: 'button', className: 'rl-fullscreen' }),
      help: el('button', { type: 'button', className: 'rl-help' }),
    };
    this.toolbar.append(...Object.values(this.buttons));

    /** @internal */
    this.panel = el('div', { className: 'rl-panel' });
    /** @internal */
    this.heading = el('h2');
    /** @internal */
    this.paperCard = el('section', { className: 'rl-paper', hidden: true });
    this.paperCard.id = `${id}-paper`;
    /** @internal */
    // a group, not a form: Enter in a field of a form in a sandboxed frame without allow-forms is a
    // blocked submission the console reports (course systems frame the page that way)
    this.form = el('div', { className: 'rl-controls' });
    this.form.setAttribute('role', 'group');
    /** @internal */
    this.player = el('div', { className: 'rl-player', hidden: true });
    /** @internal */
    this.readout = el('dl', { className: 'rl-readout' });
    /** @internal */
    this.note = el('p', { className: 'rl-readout-note', hidden: true });
    /** @internal */
    this.claims = el('ul', { className: 'rl-claims', hidden: true });
    /** @internal what the edited input leaves undefined ("rulings 4 and 5 are parallel: δ undefined") */
    this.problems = el('ul', { className: 'rl-problems', hidden: true });
    /** @internal the exercise: prompt, answers, Check, hints (task/panel.js) */
    this.taskBox = el('section', { className: 'rl-task', hidden: true });
    /** the place of the page's "Make an exercise" panel (task/author.js) */
    this.authorBox = el('section', { className: 'rl-author', hidden: true });
    /** @internal "edited from: …", with the way back to the built-in input */
    this.edited = el('div', { className: 'rl-edited', hidden: true });
    /** @internal "Edit as data": a scene without handles hands its sample to "Your data" */
    this.asData = el('button', { type: 'button', className: 'rl-as-data', hidden: true });
    /** @internal */
    this.caption = el('p', { className: 'rl-caption' });
    /** @internal */
    this.figure = el('figure', { className: 'rl-figure' });
    /** @internal */
    this.downloads = el('div', { className: 'rl-downloads' });
    /** @internal */
    this.text = el('article', { className: 'rl-text' });
    this.panel.append(
      this.heading,
      this.authorBox,
      this.taskBox,
      this.paperCard,
      this.edited,
      this.form,
      this.asData,
      this.player,
      this.readout,
      this.problems,
      this.claims,
      this.note,
      this.caption,
      this.figure,
      this.downloads,
      this.text,
    );
    this.root.append(this.view, this.panel);
    /** @internal */
    this.shortcuts = /** @type {HTMLDialogElement} */ (el('dialog', { className: 'rl-shortcuts' }));
    this.root.append(this.shortcuts);
    host.append(this.root);

    this.viewer = new Viewer(this.canvas, this.labels);
    // in a narrow box the legend spans the top of the view and the buttons its bottom: the
    // figure is framed between them
    this.viewer.insets = () => {
      if (!this.root.classList.contains('rl-narrow')) return { top: 0, bottom: 0 };
      const view = this.view.getBoundingClientRect();
      if (!view.height) return { top: 0, bottom: 0 };
      const legend =
        this.legend.hidden || !this.view.contains(this.legend) ? null : this.legend.getBoundingClientRect();
      const bar = this.toolbar.getBoundingClientRect();
      return {
        top: legend ? Math.max(0, legend.bottom - view.top) / view.height : 0,
        bottom: Math.max(0, view.bottom - bar.top) / view.height,
      };
    };
    /** @internal */
    this.session = new SceneSession(this.viewer, {
      onBuilt: (built, final) => this.shown(built, final),
      onError: (e) => this.fail(e),
      onProgress: (f) => {
        this.progress.hidden = f === null;
        if (f !== null) this.progressBar.value = f;
      },
    });
    /** @internal */
    this.playerControl = new Player((key, value) =>
      this.setParam(key, Number(value.toFixed(Player.stepped(this.param(key)) ? 0 : 4)), false),
    );
    /** @type {import('./scene.js').Scene | null} */
    this.scene = null;
    /** @type {import('./scene.js').Params} */
    this.params = {};
    /** @type {import('./scene.js').ImportedData | null} */
    this.data = null;
    /** @type {import('./paper.js').PaperPreset | null} the figure of the paper shown, if any */
    this.paper = null;
    /** @internal @type {boolean | undefined} whether the reader opened (or closed) the figure's card */
    this.paperOpen = undefined;
    /** @internal @type {ReturnType<typeof buildControls> | null} */
    this.controls = null;
    /** @internal */
    this.lastAnnounced = 0;
    /** @internal @type {string | null} the parameter the reader changed last (an error names its field) */
    this.lastChanged = null;
    /** @internal */
    this.announceTimer = 0;
    /** @type {import('./scene.js').Input | null} the reader's edit of the scene's input (null: the built-in input) */
    this.input = null;
    /** the i18n key of a note about the edit (too large for the link), or '' */
    this.inputNote = '';
    /** @type {import('./task/format.js').Task | null} the exercise being done, if any */
    this.task = null;
    /** @internal @type {import('./scene.js').Input | null} the exercise's start edit */
    this.taskInput = null;
    /** @internal */
    this.taskPanel = new TaskPanel(this.taskBox, {
      i18n: () => this.i18n,
      state: () => {
        const built = this.session.built;
        if (!built || !this.scene || this.root.classList.contains('rl-stale')) return null;
        return { scene: this.scene, params: this.params, context: this.context(), built };
      },
      startOver: () => this.startTask(),
      showSolution: () => this.solveTask(),
      leave: options.onLeaveTask ? () => options.onLeaveTask?.() : null,
      report: (type, report) => {
        if (type === 'solved') this.say(this.i18n.t('task.solved'));
        this.options.onTask?.(type, report);
      },
    });
    /** @internal The handles of the scene's input: grabbed by pointer, finger and keyboard. */
    this.editor = new Editor(this.view, this.viewer, {
      i18n: () => this.i18n,
      current: () => this.input,
      base: () => (this.task ? this.taskInput : null),
      apply: (input, ended, said) => this.setInput(input, ended, said),
      say: (text) => this.say(text),
      changed: () => this.showEditing(),
    });
    this.editor.enabled = !!options.editable;
    this.viewer.overlays.push((m) => this.editor.place(m));

    this.viewer.onCameraChange = (ended) => {
      this.options.onChange?.({ reason: 'camera', ended });
      if (ended) this.announce();
    };
    this.buttons.fit.addEventListener('click', () => {
      this.viewer.fit();
      this.options.onChange?.({ reason: 'camera', ended: true });
    });
    this.buttons.reset.addEventListener('click', () => this.reset());
    this.buttons.fullscreen.addEventListener('click', () => this.toggleFullscreen());
    this.buttons.help.addEventListener('click', () => this.showShortcuts());
    this.buttons.edit.addEventListener('click', () => {
      this.editor.setEditing(!this.editor.editing);
      if (this.editor.editing) this.canvas.focus();
    });
    this.buttons.undo.addEventListener('click', () => this.editor.undo());
    this.buttons.redo.addEventListener('click', () => this.editor.redo());
    this.done.addEventListener('click', () => this.editor.setEditing(false));
    for (const [mode, button] of Object.entries(this.modes))
      button.addEventListener('click', () =>
        this.editor.setMode(/** @type {import('./edit/geometry.js').MoveMode} */ (mode)),
      );
    this.asData.addEventListener('click', () => {
      const data = this.session.built?.data;
      if (data) this.options.onEditAsData?.({ segments: data.segments, ...(data.grid ?? {}) });
    });
    this.cancel.addEventListener('click', () => {
      this.session.dispose();
      this.progress.hidden = true;
    });
    this.root.addEventListener('keydown', (e) => this.key(e));
    // the page's stage also takes the keys pressed with nothing focused (undo after a drag elsewhere)
    if (options.page)
      doc.addEventListener('keydown', (e) => {
        if (e.target === doc.body) this.key(e);
      });
    /** @internal */
    this.resize = new ResizeObserver(() => this.layout());
    this.resize.observe(this.root);
    this.setPanel(options.controls ?? true, options.text ?? true);
    this.localize();
  }

  /** @internal The Param of the current scene named `key`. */
  param(/** @type {string} */ key) {
    return /** @type {import('./scene.js').Param} */ (this.scene?.params.find((p) => p.key === key));
  }

  /** Shows or hides the controls and the explanation. */
  setPanel(/** @type {boolean} */ controls, /** @type {boolean} */ text) {
    /** @internal */
    this.showControls = controls;
    /** @internal */
    this.showText = text;
    this.root.classList.toggle('rl-no-controls', !controls);
    this.text.hidden = !text || !!this.task?.hide.includes('text');
    this.heading.hidden = !controls && !text;
    this.panel.hidden = !controls && !text;
    this.root.classList.toggle('rl-no-panel', !controls && !text);
    this.layout();
  }

  /**
   * Panel beside the view when there is room, under it otherwise (narrow: under NARROW px, or a
   * box taller than wide under PORTRAIT px); the labels above the controls when tiny. The box is
   * the element's, or for the page the screen.
   * @internal
   */
  layout() {
    const before = this.root.className;
    const box = this.root.getBoundingClientRect();
    const width = box.width || this.host.getBoundingClientRect().width;
    const height = this.options.page ? window.innerHeight : box.height || this.host.getBoundingClientRect().height;
    const narrow = width > 0 && (width < NARROW || (height > width && width < PORTRAIT));
    this.root.classList.toggle('rl-narrow', narrow);
    // in a narrow box with a panel the legend leads the panel, right under the view: the view
    // keeps its whole height for the figure
    const legendInPanel = narrow && !this.panel.hidden && !!this.showControls;
    if (legendInPanel && this.legend.parentElement !== this.panel) this.panel.prepend(this.legend);
    if (!legendInPanel && this.legend.parentElement !== this.view) this.view.insertBefore(this.legend, this.bar);
    this.legend.classList.toggle('rl-legend-panel', legendInPanel);
    this.root.classList.toggle('rl-tiny', width > 0 && width < TINY);
    // the hint under the view only where it fits beside the toolbar on one line
    this.root.classList.toggle('rl-view-small', this.view.getBoundingClientRect().width < SMALL_VIEW);
    this.controls?.fit();
    // a new arrangement moves the view (a view resized alone is redrawn by the viewer itself)
    if (this.root.className !== before) this.viewer.requestRender();
  }

  /** @internal The texts that depend on the language but not on the scene. */
  localize() {
    const { t } = this.i18n;
    this.canvas.setAttribute('aria-label', t('view.label'));
    // a word, and a sign that stands in for it where the box is narrow (the name stays the word)
    const label = (/** @type {HTMLElement} */ button, /** @type {string} */ sign, /** @type {string} */ word) => {
      const icon = Object.assign(this.root.ownerDocument.createElement('span'), {
        className: 'rl-btn-sign',
        textContent: sign,
      });
      icon.setAttribute('aria-hidden', 'true');
      const text = Object.assign(this.root.ownerDocument.createElement('span'), {
        className: 'rl-btn-word',
        textContent: word,
      });
      button.replaceChildren(icon, text);
      button.setAttribute('aria-label', word);
    };
    label(this.buttons.fit, '⌂', t('view.fit'));
    this.buttons.fit.title = t('view.fitTitle');
    label(this.buttons.reset, '↺', t('view.reset'));
    this.buttons.reset.title = t('view.resetTitle');
    label(this.buttons.fullscreen, '⤢', t('view.fullscreen'));
    // a frame without allow="fullscreen" cannot: no button that does nothing
    this.buttons.fullscreen.hidden = !canFullscreen(this.root.ownerDocument);
    this.buttons.help.textContent = '?';
    this.buttons.help.setAttribute('aria-label', t('view.shortcuts'));
    this.buttons.help.title = t('view.shortcuts');
    this.cancel.textContent = t('view.cancel');
    this.legend.setAttribute('aria-label', t('view.legend'));
    this.form.setAttribute('aria-label', t('panel.controls'));
    this.readout.setAttribute('aria-label', t('panel.readout'));
    this.hint.textContent = t(touchScreen() ? 'view.hintTouch' : 'view.hintMouse');
    label(this.buttons.edit, '✎', t('edit.button'));
    this.buttons.edit.title = t('edit.buttonTitle');
    this.buttons.undo.textContent = '↶';
    this.buttons.undo.setAttribute('aria-label', t('edit.undo'));
    this.buttons.undo.title = t('edit.undoTitle');
    this.buttons.redo.textContent = '↷';
    this.buttons.redo.setAttribute('aria-label', t('edit.redo'));
    this.buttons.redo.title = t('edit.redoTitle');
    this.modeLabel.textContent = t('edit.moveLabel');
    this.modeGroup.setAttribute('aria-label', t('edit.moveLabel'));
    const MODE_SIGNS = { view: '⊙', line: '⤡', vertical: '↕' };
    for (const [mode, button] of Object.entries(this.modes)) {
      label(button, MODE_SIGNS[/** @type {keyof typeof MODE_SIGNS} */ (mode)], t(`edit.mode.${mode}`));
      button.title = t(`edit.mode.${mode}Title`);
    }
    this.done.textContent = t('edit.done');
    this.asData.textContent = t('edit.asData');
    // the shortcuts' dialog is built when it opens (a closed panel costs the start nothing)
    if (this.shortcuts.open) this.buildShortcuts();
    this.showEditing();
  }

  /** Whether the reader may drag the scene's handles. */
  setEditable(/** @type {boolean} */ on) {
    this.editor.enabled = on;
    if (!on) this.editor.setEditing(false);
    this.showEditing();
    this.viewer.requestRender();
  }

  /**
   * Computes the scene on an edited input (null: the built-in one) — a handle was moved, a step
   * undone, the input replaced; `ended`: the step is over (the link is written, `change` fired).
   * @param {import('./scene.js').Input | null} input
   * @param {boolean} ended
   * @param {string} [said]   what the step did, said before the readout once it has ended
   */
  setInput(input, ended, said = '') {
    if (!this.scene) return;
    this.input = input ? copyInput(input) : null;
    this.compute();
    this.controls?.update(this.params);
    this.showEditing();
    this.options.onChange?.({ reason: 'input', ended });
    if (ended) this.announce(said);
  }

  /**
   * Opens an exercise (task/format.js) in `scene`: its start state, what it lets change (the
   * rest held), what it hides; `state` restores a reader's progress (parameters the exercise lets
   * change, an edit where handles may move). null leaves the exercise (the scene stays).
   * @param {import('./task/format.js').Task | null} task
   * @param {import('./scene.js').Scene | null} [scene]
   * @param {{params?: import('./scene.js').Params, input?: import('./scene.js').Input | null, camera?: number[] | null, notes?: Array<{key: string, note: string, vars?: Record<string, string>}>}} [state]
   */
  async openTask(task, scene = null, state = {}) {
    if (!task || !scene) {
      this.task = null;
      this.taskInput = null;
      this.taskPanel.show(null);
      this.editor.enabled = !!this.options.editable;
      if (this.scene)
        this.enter(this.scene, this.params, { camera: this.viewer.camera.toArray(), fit: false, input: this.input });
      return;
    }
    this.task = task;
    this.paper = null;
    this.taskInput = task.input ? decodeInput(task.input) : null;
    this.editor.enabled = task.change.includes('handles');
    const kept = Object.fromEntries(Object.entries(state.params ?? {}).filter(([k]) => task.change.includes(k)));
    const input = task.change.includes('handles') && state.input ? state.input : this.taskInput;
    await this.open(
      scene,
      { ...withChoices(scene, task.params), ...kept },
      {
        camera: state.camera ?? null,
        input,
        notes: state.notes ?? [],
        task: true,
      },
    );
    this.taskPanel.show(task);
    this.showEditing();
  }

  /** Back to the exercise's start (its parameters and edit). */
  startTask() {
    const task = this.task;
    if (!task || !this.scene) return;
    this.enter(this.scene, withChoices(this.scene, task.params), { fit: true, input: this.taskInput });
    this.options.onChange?.({ reason: 'reset', ended: true });
  }

  /** The exercise's solution state (its parameters and edit) on screen. */
  solveTask() {
    const task = this.task;
    if (!task?.solution || !this.scene) return;
    const solution = task.solution;
    const input = solution.input ? decodeInput(solution.input) : this.taskInput;
    this.enter(this.scene, withChoices(this.scene, { ...task.params, ...(solution.params ?? {}) }), {
      camera: this.viewer.camera.toArray(),
      fit: false,
      input,
    });
    this.options.onChange?.({ reason: 'param', ended: true });
  }

  /** The current input of the scene's handles (the edit, or the built-in input), copied; null without handles. */
  currentInput() {
    const sets = this.session.built?.input?.sets;
    if (this.input) return copyInput(this.input);
    return sets?.length ? inputOf(sets) : null;
  }

  /** @internal Says `text` to screen readers (the live region). */
  say(/** @type {string} */ text) {
    this.status.textContent = text;
  }

  /** @internal The edit's buttons, its bar and its note, as the editor and the input stand. */
  showEditing() {
    const { t } = this.i18n;
    const editor = this.editor;
    if (!editor) return;
    const active = editor.active;
    this.buttons.edit.hidden = !active;
    this.buttons.edit.setAttribute('aria-pressed', String(editor.editing));
    this.buttons.undo.hidden = this.buttons.redo.hidden = !active || (!editor.canUndo && !editor.canRedo);
    this.buttons.undo.disabled = !editor.canUndo;
    this.buttons.redo.disabled = !editor.canRedo;
    this.editBar.hidden = !editor.editing;
    for (const [mode, button] of Object.entries(this.modes))
      button.setAttribute('aria-pressed', String(editor.mode === mode));
    this.modes.line.hidden = !editor.sets.some((set) => set.shape === 'pairs');
    const doc = this.root.ownerDocument;
    // (in an exercise its own Start over takes the note's place)
    this.edited.hidden = !this.input || !!this.task;
    if (this.input && !this.task) {
      const text = doc.createElement('p');
      appendRich(text, t('edit.from', { from: editor.from }));
      const back = Object.assign(doc.createElement('button'), { type: 'button', textContent: t('edit.restore') });
      back.addEventListener('click', () => this.editor.restore());
      const parts = [text, back];
      if (this.inputNote)
        parts.push(
          Object.assign(doc.createElement('p'), { className: 'rl-edited-note', textContent: t(this.inputNote) }),
        );
      this.edited.replaceChildren(...parts);
    }
    this.root.classList.toggle('rl-has-handles', active);
    const touch = touchScreen();
    this.hint.textContent = t(
      touch ? (active ? 'view.hintTouchEdit' : 'view.hintTouch') : active ? 'view.hintEdit' : 'view.hintMouse',
    );
  }

  /** The language (a code of i18n/index.js, or null for the browser's). */
  setLanguage(/** @type {string | null} */ lang) {
    this.i18n = translator(pickLanguage(lang));
    this.localize();
    if (this.scene) {
      this.enter(this.scene, this.params, {
        camera: this.viewer.camera.toArray(),
        fit: false,
        input: this.input,
        history: true,
      });
      // (a computation that fails keeps the last picture: its legend speaks the new language too)
      showLegend(this.legend, this.scene, this.params, this.i18n.t);
      this.taskPanel.render();
    }
  }

  /**
   * Opens a scene with `params` (missing ones take their defaults).
   * @param {import('./scene.js').Scene} scene
   * @param {import('./scene.js').Params} params
   * @param {{camera?: number[] | null, fit?: boolean, data?: import('./scene.js').ImportedData | null, notes?: Array<{key: string, note: string, vars?: Record<string, string>}>, autoplay?: boolean, paper?: import('./paper.js').PaperPreset | null, input?: import('./scene.js').Input | null, inputNote?: string, task?: boolean}} [options]
   *   task: the exercise shown stays (openTask); otherwise opening a scene leaves it
   */
  async open(scene, params, options = {}) {
    if (this.task && !options.task) {
      this.task = null;
      this.taskInput = null;
      this.taskPanel.show(null);
      this.editor.enabled = !!this.options.editable;
    }
    try {
      await start();
    } catch (e) {
      this.fail(e);
      throw e;
    }
    if (options.data !== undefined) this.data = options.data;
    this.paper = options.paper && options.paper.scene === scene.id ? options.paper : null;
    const notes = [...(options.notes ?? [])];
    this.inputNote = options.inputNote ?? '';
    const fits = this.enter(
      scene,
      { ...defaults(scene), ...params },
      {
        camera: options.camera ?? null,
        fit: true,
        input: options.input ?? null,
      },
    );
    if (!fits) notes.push({ key: 'input', note: 'note.badInput' });
    this.showNotes(notes);
    if (options.autoplay && !Player.reducedMotion()) {
      const key = this.playableKey();
      if (key) this.togglePlay(key);
    }
  }

  /**
   * Shows the heading and the explanation of `scene` before it can be opened (the core still
   * loading): the reader reads while the figure is on its way. open() shows them again.
   * @param {import('./scene.js').Scene} scene
   */
  preview(scene) {
    const { t } = this.i18n;
    this.heading.textContent = '';
    appendRich(this.heading, t(scene.title));
    // the explanation is markup from the project's own language files (never user text)
    this.text.innerHTML = t(scene.text);
  }

  /**
   * @param {import('./scene.js').Scene} scene
   * @param {import('./scene.js').Params} params
   * @param {{camera?: number[] | null, fit?: boolean, input?: import('./scene.js').Input | null, history?: boolean}} options
   *   input: an edit to show (kept only where it fits the scene's handles); history: keep the
   *   edit's undo steps (a change of language)
   * @returns {boolean} whether the input given (if any) fits
   * @internal
   */
  enter(scene, params, { camera = null, fit = true, input = null, history = false }) {
    const { t } = this.i18n;
    if (this.scene !== scene) this.stopPlaying();
    this.input = null;
    if (!history) this.editor.cancel();
    this.scene = scene;
    this.params = { ...params };
    this.heading.textContent = '';
    appendRich(this.heading, t(scene.title));
    // the explanation is markup from the project's own language files (never user text)
    this.text.innerHTML = t(scene.text);
    // (an exercise may hide it where it would say the answer)
    this.text.hidden = !this.showText || !!this.task?.hide.includes('text');
    this.controls = buildControls(this.form, scene, this.params, this.i18n, {
      onChange: (key, value, ended) => this.setParam(key, value, ended),
      onPlay: (key) => this.togglePlay(key),
      fixed: (p) => this.heldReason(p.key),
    });
    // an exercise's hidden parameters (an answer-revealing layer) are not shown at all
    for (const key of this.task?.hide ?? []) {
      const row = this.controls.rows.get(key)?.row;
      if (row) row.hidden = true;
    }
    this.controls.fit();
    this.buildPlayer();
    this.showPaper();
    // the built-in input first: its handles set the box they stay in and say what was edited
    const built = this.compute({ fit: fit && !camera });
    const editable = built?.input;
    if (history) this.editor.show(editable);
    else this.editor.enter(editable);
    const fits = !input || (!!editable && fitsSets(input, editable.sets));
    if (input && fits) {
      this.input = copyInput(input);
      this.compute();
      this.controls.update(this.params);
    }
    this.showEditing();
    if (camera) {
      this.viewer.camera.fromArray(camera);
      this.viewer.requestRender();
    }
    return fits;
  }

  /**
   * Why parameter `key` is held where it is (an i18n key), or null: an exercise holds what it
   * does not let change, an edit of the input holds what would replace it. A held parameter
   * changes by no route — slider, − / +, its field, play, single step, setParam.
   */
  heldReason(/** @type {string} */ key) {
    if (this.task && !this.task.change.includes(key)) return 'task.reason.locked';
    if (this.input && !this.task && this.scene?.fixed?.includes(key)) return 'edit.reason.fixed';
    return null;
  }

  /** @internal The parameter Space plays and "." steps: the one playing, or the first that may move now. */
  playableKey() {
    return (
      this.playerControl.param?.key ??
      this.scene?.params.find((p) => p.play && !p.unless?.(this.params) && !this.heldReason(p.key))?.key
    );
  }

  /** Sets one parameter and recomputes (not one that is held: heldReason). */
  setParam(/** @type {string} */ key, /** @type {number | string | boolean} */ value, ended = true) {
    if (this.heldReason(key)) return;
    if (!this.scene || this.params[key] === value) {
      if (ended) {
        this.options.onChange?.({ reason: 'param', ended: true });
        this.announce();
      }
      return;
    }
    const p = this.param(key);
    this.lastChanged = key;
    this.params = { ...this.params, [key]: value, ...(p?.sets?.(value, this.params) ?? {}) };
    this.controls?.update(this.params);
    this.showPaper();
    this.compute({ fit: p?.type === 'select' && p.refit !== false });
    this.options.onChange?.({ reason: 'param', ended });
    if (ended) this.announce();
  }

  /** @internal What a scene's create() is given besides its parameters, now. */
  context() {
    return {
      t: this.i18n.t,
      format: this.i18n.format,
      lang: this.i18n.lang,
      data: this.data ?? undefined,
      refine: refineInWorker,
      input: this.input ?? undefined,
    };
  }

  /** @internal Recomputes the scene for the current parameters (and input); returns what it built, or null. */
  compute({ fit = false } = {}) {
    if (!this.scene) return null;
    const built = this.session.show(this.scene, this.params, this.context(), { fit });
    this.root.classList.toggle('rl-stale', !built);
    if (built) this.error.hidden = true;
    return built;
  }

  /**
   * The card of the paper's figure shown (if any): its caption, what ruledlab shows and whose
   * data it is, where ruledlab goes beyond the paper, and — once a control has moved — the way
   * back to the figure's own settings.
   * @internal
   */
  showPaper() {
    const card = this.paperCard;
    const preset = this.task ? null : this.paper;
    card.hidden = !preset || !this.scene;
    if (!preset || !this.scene) return card.replaceChildren();
    const { t } = this.i18n;
    const doc = this.root.ownerDocument;
    const el = (/** @type {string} */ tag, /** @type {string} */ className, /** @type {string} */ text) =>
      appendRich(Object.assign(doc.createElement(tag), { className }), text);
    const heading = el('h3', 'rl-paper-title', t('paper.heading', { figure: t(preset.label) }));
    heading.id = `${card.id}-title`;
    card.setAttribute('aria-labelledby', heading.id);
    const caption = el('blockquote', 'rl-paper-caption', t(preset.caption));
    const note = el('p', 'rl-paper-note', t(preset.note));
    const data = el('p', `rl-paper-data rl-data-${preset.data}`, t(`paper.data.${preset.data}`));
    // the heading opens and closes the rest: open beside the view, closed over the controls of a
    // narrow box (one line instead of a screenful before the first slider), as the reader left it
    const more = /** @type {HTMLDetailsElement} */ (doc.createElement('details'));
    more.className = 'rl-paper-more';
    more.open = this.paperOpen ?? !this.root.classList.contains('rl-narrow');
    more.addEventListener('toggle', () => (this.paperOpen = more.open));
    const summary = doc.createElement('summary');
    summary.append(heading);
    more.append(summary, caption, note, data);
    card.replaceChildren(more);
    if (preset.beyond) {
      const beyond = doc.createElement('p');
      beyond.className = 'rl-beyond';
      beyond.append(Object.assign(doc.createElement('strong'), { textContent: `${t('paper.beyondTitle')} ` }));
      appendRich(beyond, t(preset.beyond));
      more.append(beyond);
    }
    if (!atPreset(preset, this.scene, this.params)) {
      const changed = el('p', 'rl-paper-changed', `${t('paper.changed')} `);
      const back = Object.assign(doc.createElement('button'), {
        type: 'button',
        textContent: t('paper.back', { figure: t(preset.label) }),
      });
      back.addEventListener('click', () => {
        if (!this.scene) return;
        this.stopPlaying();
        this.enter(this.scene, { ...defaults(this.scene), ...preset.params }, { fit: true });
        this.options.onChange?.({ reason: 'param', ended: true });
        this.announce();
        // the button is gone with the change: keep the keyboard in the controls
        /** @type {HTMLElement | null} */ (this.form.querySelector('[name]'))?.focus();
      });
      changed.append(back);
      card.append(changed);
    }
  }

  /** @internal After a computation: legend, readout, description, downloads, figure. */
  shown(/** @type {import('./scene.js').Built} */ built, /** @type {boolean} */ final) {
    if (!this.scene) return;
    const { t } = this.i18n;
    showLegend(this.legend, this.scene, this.params, t);
    // the legend may cover another share of a narrow view now: a fitted view is framed anew (not
    // while the reader moves the geometry: the view holds still under the pointer)
    if (this.root.classList.contains('rl-narrow') && this.viewer.camera.atHome() && !this.input) this.viewer.fit();
    // the handles where the core has them (an edit comes back in the core's own form: a tool
    // axis keeps the tool's length); the edit itself stays as the reader made it, bit for bit
    this.editor.show(built.input);
    this.problems.replaceChildren(
      ...(built.problems ?? []).map((text) => {
        const li = this.root.ownerDocument.createElement('li');
        appendRich(li, text);
        return li;
      }),
    );
    this.problems.hidden = !built.problems?.length;
    this.asData.hidden = !(this.scene.editAsData && built.data && this.options.onEditAsData && this.editor.enabled);
    // an exercise hides what would give its answer away (the readout and the sentences that say it)
    const hidden = this.task?.hide ?? [];
    const readouts = (built.readouts ?? []).filter((r) => !hidden.includes(r.label));
    showReadout(this.readout, readouts, this.i18n);
    showClaims(this.claims, hidden.includes('claims') ? [] : (built.claims ?? []), t);
    this.note.hidden = !built.note;
    this.note.textContent = built.note ?? '';
    const description = this.task && hidden.length ? say(this.task.title, this.i18n.lang) : built.description;
    this.description.replaceChildren();
    appendRich(this.description, description);
    this.caption.replaceChildren();
    appendRich(this.caption, description);
    this.figure.replaceChildren(...(built.figure ? [built.figure()] : []));
    this.downloads.replaceChildren(
      ...(built.downloads ?? []).map((d) => {
        const b = Object.assign(this.root.ownerDocument.createElement('button'), {
          type: 'button',
          textContent: t(d.label),
        });
        b.addEventListener('click', () =>
          download(d.filename, typeof d.content === 'function' ? d.content() : d.content, d.type),
        );
        return b;
      }),
    );
    for (const key of this.scene.params.map((p) => p.key)) this.controls?.invalid(key, null);
    this.root.dataset.scene = this.scene.id;
    this.root.dataset.paper = this.paper?.id ?? '';
    if (final) this.root.dataset.ready = '1';
    else delete this.root.dataset.ready;
    this.options.onBuilt?.(built);
  }

  /**
   * Shows an error in the view (and next to the control it concerns), in the view's language;
   * the last picture stays. Returns the sentence shown.
   * @internal
   */
  fail(/** @type {unknown} */ e) {
    const error = /** @type {any} */ (e);
    const option = error?.details?.option;
    // the field it concerns: of the scene's candidates, the one the reader changed last
    const candidates = [this.scene && option ? this.scene.fieldOf?.(option) : null]
      .flat()
      .filter((k) => typeof k === 'string');
    const key = candidates.includes(this.lastChanged ?? '') ? this.lastChanged : (candidates[0] ?? null);
    // named as the page names it: the option's own name ("the interval of u"), else the field's
    const { t, has } = this.i18n;
    const name =
      option && has(`error.option.${option}`) ? t(`error.option.${option}`) : key ? this.fieldName(key) : undefined;
    const message = describeError(e, this.i18n, name);
    this.error.hidden = false;
    // beside its field the whole sentence; over the view (small on a phone) where to look
    this.error.textContent = key && this.showControls ? t('error.seeField', { field: this.fieldName(key) }) : message;
    // the field the reader just changed keeps no old message when the error is now elsewhere (it
    // was fixed, or the core has not come to it: it says so again once the other is fixed)
    if (this.lastChanged && this.lastChanged !== key) this.controls?.invalid(this.lastChanged, null);
    if (key) this.controls?.invalid(key, message);
    // an edit the core cannot compute on: said under the readout too (the drag can go on, undo back)
    if (this.input) {
      this.problems.replaceChildren(
        Object.assign(this.root.ownerDocument.createElement('li'), { textContent: message }),
      );
      this.problems.hidden = false;
    }
    this.options.onError?.(e, message);
    return message;
  }

  /** @internal The name of the field of parameter `key` in messages ("the z component of e(u)"), or its label. */
  fieldName(/** @type {string} */ key) {
    const p = this.param(key);
    if (!p) return key;
    const { t, has } = this.i18n;
    return has(`${p.label}.field`) ? t(`${p.label}.field`) : plainRich(t(p.label));
  }

  /** @internal Notes about link values that were not used. */
  showNotes(/** @type {Array<{key: string, note: string, vars?: Record<string, string>}>} */ notes) {
    const { t } = this.i18n;
    const doc = this.root.ownerDocument;
    this.noteBox.hidden = notes.length === 0;
    // read once, then out of the figure's way
    const close = Object.assign(doc.createElement('button'), {
      type: 'button',
      className: 'rl-note-close',
      textContent: '×',
    });
    close.setAttribute('aria-label', t('view.closeNote'));
    close.addEventListener('click', () => (this.noteBox.hidden = true));
    const text = doc.createElement('span');
    text.textContent = notes.map(({ key, note, vars }) => t(note, { key, ...vars })).join(' ');
    this.noteBox.replaceChildren(text, close);
  }

  /** @internal Announces the readout to screen readers: only when an interaction ends, at most once a second. */
  announce(/** @type {string} */ prefix = '') {
    const now = performance.now();
    clearTimeout(this.announceTimer);
    const say = () => {
      this.lastAnnounced = performance.now();
      const built = this.session.built;
      const hidden = this.task?.hide ?? [];
      const sentence = built
        ? readoutSentence(
            (built.readouts ?? []).filter((r) => !hidden.includes(r.label)),
            this.i18n,
          )
        : '';
      if (built || prefix) this.status.textContent = [prefix, sentence].filter(Boolean).join('. ');
    };
    const wait = this.lastAnnounced + ANNOUNCE_EVERY - now;
    if (wait <= 0) say();
    else this.announceTimer = window.setTimeout(say, wait);
  }

  /** @internal The player row: speed and single step, shown when the scene has a playable parameter. */
  buildPlayer() {
    const { t } = this.i18n;
    const doc = this.root.ownerDocument;
    // (not a parameter an exercise holds)
    const playable = this.scene?.params.filter((p) => p.play && this.heldReason(p.key) !== 'task.reason.locked') ?? [];
    this.player.hidden = playable.length === 0;
    this.player.replaceChildren();
    if (!playable.length) return;
    const speedLabel = Object.assign(doc.createElement('label'), { textContent: t('player.speed') });
    const speed = doc.createElement('select');
    for (const s of [0.25, 0.5, 1, 2, 4])
      speed.add(new Option(`${this.i18n.lang === 'de' ? String(s).replace('.', ',') : s}×`, String(s)));
    speed.value = String(this.playerControl.speed);
    speed.addEventListener('change', () => (this.playerControl.speed = Number(speed.value)));
    speedLabel.append(' ', speed);
    const step = Object.assign(doc.createElement('button'), { type: 'button', textContent: t('player.step') });
    step.addEventListener('click', () => {
      const key = this.playableKey();
      if (!key) return;
      this.stopPlaying();
      this.playerControl.step(this.param(key), Number(this.params[key]));
      this.announce();
    });
    this.player.append(speedLabel, step);
  }

  /** @internal Plays or pauses parameter `key`. */
  togglePlay(/** @type {string} */ key) {
    const p = this.param(key);
    if (!p || this.heldReason(key)) return;
    if (this.playerControl.playing && this.playerControl.param?.key === key) {
      this.stopPlaying();
      this.announce();
      return;
    }
    this.playerControl.play(p, Number(this.params[key]));
    this.controls?.playing(key);
  }

  /** @internal */
  stopPlaying() {
    if (this.playerControl.playing) this.options.onChange?.({ reason: 'param', ended: true });
    this.playerControl.stop();
    this.controls?.playing(null);
  }

  /** The scene's defaults and its fitted camera (in an exercise: its start; with an edit: the built-in input, undoably). */
  reset() {
    if (!this.scene) return;
    if (this.task) {
      this.taskPanel.show(this.task);
      return this.startTask();
    }
    this.stopPlaying();
    // an edit is taken back first, as one step of undo (↶ brings it back); pressed again, Reset
    // resets the controls
    if (this.input && this.editor.enabled) {
      this.editor.restore();
      this.viewer.fit();
      return;
    }
    this.enter(this.scene, defaults(this.scene), { fit: true });
    this.options.onChange?.({ reason: 'reset', ended: true });
    this.announce();
  }

  /** Fullscreen for the whole stage (view and panel), or back. */
  toggleFullscreen() {
    const doc = this.root.ownerDocument;
    if (doc.fullscreenElement) doc.exitFullscreen?.();
    else this.root.requestFullscreen?.().catch(() => {});
  }

  /** @internal Keys of the stage: ? shortcuts, R reset, Space play/pause, . single step (the view's own keys are the camera's). */
  key(/** @type {KeyboardEvent} */ e) {
    const target = /** @type {HTMLElement} */ (e.target);
    const typing = target.matches?.('input[type=text], textarea, select');
    if (typing) return;
    // undo and redo of the edit, wherever the keyboard is in the stage
    if ((e.ctrlKey || e.metaKey) && !e.altKey && this.editor.active) {
      const k = e.key.toLowerCase();
      if (k === 'z' || k === 'y') {
        e.preventDefault();
        if (k === 'y' || e.shiftKey) this.editor.redo();
        else this.editor.undo();
      }
      return;
    }
    if (e.ctrlKey || e.metaKey || e.altKey) return;
    if (target === this.canvas && (e.key === 'e' || e.key === 'E') && this.editor.active) {
      e.preventDefault();
      this.editor.setEditing(!this.editor.editing);
    } else if (e.key === '?') {
      e.preventDefault();
      this.showShortcuts();
    } else if (target === this.canvas && (e.key === 'r' || e.key === 'R')) {
      e.preventDefault();
      this.reset();
    } else if (target === this.canvas && e.key === ' ') {
      e.preventDefault();
      const key = this.playableKey();
      if (key) this.togglePlay(key);
    } else if (target === this.canvas && e.key === '.') {
      e.preventDefault();
      /** @type {HTMLButtonElement | null} */ (this.player.querySelector('button'))?.click();
    }
  }

  /** @internal The list of gestures (first, on a touch screen) and keys that "?" shows. */
  buildShortcuts() {
    const { t } = this.i18n;
    const doc = this.root.ownerDocument;
    /** @param {Array<[string, string]>} rows @param {boolean} [keyCaps] */
    const table = (rows, keyCaps = true) => {
      const tab = doc.createElement('table');
      for (const [k, what] of rows) {
        const row = tab.insertRow();
        // keys by the names on the reader's keyboard (German: Strg, Umschalt, Leertaste, Bild↑)
        const name = keyCaps ? k.replace(/\b(Shift|Ctrl|Space|PageUp|PageDown|Enter)\b/g, (m) => t(`key.${m}`)) : t(k);
        row.insertCell().append(Object.assign(doc.createElement(keyCaps ? 'kbd' : 'strong'), { textContent: name }));
        row.insertCell().textContent = t(what);
      }
      return tab;
    };
    const keys = table([
      ['←  →  ↑  ↓', 'keys.orbit'],
      ['Shift + ←  →  ↑  ↓', 'keys.pan'],
      ['+  −', 'keys.zoom'],
      ['F', 'keys.fit'],
      ['R', 'keys.reset'],
      ['Space', 'keys.play'],
      ['.', 'keys.step'],
      ['Tab', 'keys.tab'],
      ['?', 'keys.help'],
      ['Esc', 'keys.close'],
    ]);
    const editing = table([
      ['E', 'keys.edit'],
      ['Tab  Shift+Tab  [  ]', 'keys.editStep'],
      ['←  →  ↑  ↓', 'keys.editMove'],
      ['PageUp  PageDown', 'keys.editDepth'],
      ['Shift', 'keys.editFine'],
      ['Enter', 'keys.editEnd'],
      ['Esc', 'keys.editCancel'],
      ['Ctrl+Z', 'keys.undo'],
      ['Ctrl+Shift+Z  Ctrl+Y', 'keys.redo'],
    ]);
    const touch = table(
      [
        ['touch.one', 'touch.oneWhat'],
        ['touch.two', 'touch.twoWhat'],
        ['touch.pinch', 'touch.pinchWhat'],
        ['touch.fit', 'touch.fitWhat'],
        ...(this.editor?.active
          ? /** @type {Array<[string, string]>} */ ([
              ['touch.handle', 'touch.handleWhat'],
              ['touch.hold', 'touch.holdWhat'],
            ])
          : []),
      ],
      false,
    );
    touch.className = 'rl-gestures';
    const close = Object.assign(doc.createElement('button'), { type: 'button', textContent: t('keys.closeButton') });
    close.addEventListener('click', () => this.shortcuts.close());
    const heading = (/** @type {string} */ key) => Object.assign(doc.createElement('h2'), { textContent: t(key) });
    const intro = Object.assign(doc.createElement('p'), { textContent: t('keys.intro') });
    const gestures = [heading('touch.title'), touch];
    const keyboard = [heading('keys.title'), intro, keys];
    if (this.editor?.active) keyboard.push(heading('keys.editTitle'), editing);
    this.shortcuts.setAttribute('aria-label', t(touchScreen() ? 'touch.dialog' : 'keys.title'));
    // on a touch screen the gestures come first; the keys stay for a keyboard attached to it
    // Close first: the dialog opens at its top with the keyboard on Close (a phone shows the gestures, not the end of the list)
    close.className = 'rl-shortcuts-close';
    this.shortcuts.replaceChildren(close, ...(touchScreen() ? [...gestures, ...keyboard] : [...keyboard, ...gestures]));
  }

  /** @internal */
  showShortcuts() {
    if (this.shortcuts.open) return;
    this.buildShortcuts();
    this.shortcuts.showModal?.();
    this.shortcuts.scrollTop = 0;
  }

  /** Releases the GL context, the worker's pending work and every listener. */
  dispose() {
    this.stopPlaying();
    clearTimeout(this.announceTimer);
    this.editor.dispose();
    this.session.dispose();
    this.viewer.dispose();
    this.resize.disconnect();
    this.root.remove();
  }
}

/** Whether the main pointer is a finger (a phone or tablet). */
export function touchScreen() {
  return typeof matchMedia === 'function' && matchMedia('(pointer: coarse)').matches;
}

/** Downloads `content` (a string or a Blob) as `filename`. */
export function download(/** @type {string} */ filename, /** @type {string | Blob} */ content, type = 'text/plain') {
  const blob = content instanceof Blob ? content : new Blob([content], { type });
  const a = Object.assign(document.createElement('a'), { href: URL.createObjectURL(blob), download: filename });
  a.click();
  setTimeout(() => URL.revokeObjectURL(a.href), 1000);
}
