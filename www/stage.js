// A scene on screen with everything around it: the 3D view and, beside or below it as the width
// allows, the controls, the readout, the description, the downloads and the explanation. The
// page (page/app.js) and <ruled-view> are both a Stage plus their own chrome; a Stage is told
// its state and reports every change, it never touches the URL itself.
//
// Data goes one way: state → core → what is drawn and said. The state — scene, parameters, input
// (the reader's edit), exercise, the paper's figure, imported data, language, what the panel
// shows — is the store's (store.js): a frozen object that only `dispatch(change)` replaces. The
// methods of this class (setParam, setInput, setLanguage, reset, …) and opening a scene or an
// exercise (stage/open.js) dispatch changes. After each change `render` asks the core for what the
// state shows where it changed (session.js: the scene's create()) and hands the state and what
// the core built to the parts of the stage (stage/*.js: controls, player, paper card, edit host,
// exercise host, results, shortcuts, layout) — each draws its own elements from them, asks for a
// change through the ports this class gives it, and knows no other part. The state's fields read
// here (`scene`, `params`, …) are views of the store's state: assigning one throws.
import { watchMath } from './ui/scrolling-math.js';
import { Viewer } from './viewer.js';
import { SceneSession } from './session.js';
import { defaults } from './scene.js';
import { translator, pickLanguage } from './i18n/translate.js';
import { readoutSentence } from './ui/readout.js';
import { showLegend } from './ui/legend.js';
import { appendRich } from './ui/richtext.js';
import { invariantsInWorker, refineInWorker } from './compute.js';
import { copyInput, inputOf } from './edit/input.js';
import { stageElements } from './stage/elements.js';
import { enterScene, leaveExercise, openView } from './stage/open.js';
import { wireToolbar, labelToolbar } from './stage/toolbar.js';
import { arrange, covered } from './stage/layout.js';
import { Announcer } from './stage/announcer.js';
import { PlayerRow } from './stage/player-row.js';
import { PaperCard } from './stage/paper-card.js';
import { EditHost } from './stage/edit-host.js';
import { ExerciseHost } from './stage/exercise-host.js';
import { Results } from './stage/results.js';
import { KleinPane } from './stage/klein-pane.js';
import { holdProjection } from './klein-projection.js';
import { LineMark } from './stage/line-mark.js';
import { ScenePick } from './stage/scene-pick.js';
import { Shortcuts } from './stage/shortcuts.js';
import { Store, initialState, heldReason } from './store.js';
import { cancelWork } from './compute.js';

/**
 * @typedef {import('./stage/options.js').StageOptions} StageOptions
 * @typedef {import('./stage/options.js').OpenOptions} OpenOptions
 * @typedef {import('./stage/options.js').Notes} Notes
 */

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
    /** @internal Whether openings go in tasks of their own (the page's first: stage/open.js's enterInSteps). */
    this.inSteps = false;
    /** @internal */
    this.i18n = translator(pickLanguage(options.lang));
    /** @internal */
    this.els = stageElements(host, { page: options.page });
    const els = this.els;

    /** @internal the state, and its one writer (store.js); every change is drawn by `render` */
    this.store = new Store(
      initialState({
        lang: this.i18n.lang,
        controls: options.controls ?? true,
        text: options.text ?? true,
        editable: !!options.editable,
        view: options.view === 'split' ? 'split' : 'space',
        projection: options.projection ? holdProjection(options.projection).projection : null,
      }),
      (next, previous, change) => this.render(next, previous, change),
    );

    /** the place of the page's "Make an exercise" panel (task/author.js) */
    this.authorBox = els.authorBox;
    this.viewer = new Viewer(els.canvas, els.labels);
    this.viewer.insets = () => covered(els);
    /** @internal */
    this.session = new SceneSession(this.viewer, {
      onBuilt: (built, final) => {
        this.results.render(this.state, built, final);
        this.edit.render(this.state, built);
        this.kleinPane.render(this.state, built);
        this.lineMark.render(this.state, built);
        this.scenePick.render(built);
        options.onBuilt?.(built);
      },
      onError: (e) => this.fail(e),
      onProgress: (f) => {
        els.progress.hidden = f === null;
        if (f !== null) els.progressBar.value = f;
      },
    });
    /** @internal @type {ReturnType<typeof import('./ui/controls.js').buildControls> | null} */
    this.controls = null;
    // the parts, each drawing a piece of the state; what each may ask of the stage, its ports
    const state = () => this.state;
    const i18n = () => this.i18n;
    const say = (/** @type {string} */ text) => this.announcer.say(text);
    /** @internal */
    this.announcer = new Announcer(els.status, () => {
      const built = this.session.built;
      return built ? readoutSentence(this.results.readouts(this.state, built), this.i18n) : null;
    });
    /** @internal */
    this.results = new Results({
      els,
      i18n,
      say,
      hush: () => this.announcer.cancel(),
      refit: () => {
        if (els.root.classList.contains('rl-narrow') && this.viewer.camera.atHome()) this.viewer.fit();
      },
      mark: (key, message) => this.controls?.invalid(key, message),
      onError: options.onError,
    });
    /** @internal */
    this.player = new PlayerRow(els.player, {
      state,
      i18n,
      set: (key, value, ended) => this.setParam(key, value, ended),
      announce: () => this.announce(),
      playing: (key) => this.controls?.playing(key),
    });
    /** @internal */
    this.paperCard = new PaperCard(els.paperCard, {
      i18n,
      narrow: () => els.root.classList.contains('rl-narrow'),
      back: () => this.backToPaper(),
    });
    /** @internal */
    this.exercise = new ExerciseHost(els.taskBox, {
      state,
      i18n,
      view: () => {
        const built = this.session.built;
        if (!built || !this.scene || els.root.classList.contains('rl-stale')) return null;
        return { scene: this.scene, params: this.params, context: this.context(), built };
      },
      enter: (params, input, keepCamera) => {
        if (!this.scene) return;
        this.enter(
          this.scene,
          params,
          keepCamera ? { camera: this.viewer.camera.toArray(), fit: false, input } : { fit: true, input },
        );
        this.report(keepCamera ? 'param' : 'reset', true);
      },
      leave: options.onLeaveTask
        ? () => {
            options.onLeaveTask?.();
            // (the panel is gone, and the button with it)
            this.keepKeyboard();
          }
        : null,
      mayLeave: () => options.mayLeaveTask?.() ?? true,
      solutionRule: () => options.solutionRule?.() ?? { after: 1 },
      report: (type, report) => options.onTask?.(type, report),
      say,
    });
    const mark = (/** @type {number | null} */ line) => this.dispatch({ type: 'mark', line });
    // (the reader's image: the page writes it into its link, the element into its attribute, when let go)
    const steer = (
      /** @type {import('./klein-projection.js').KleinProjection} */ projection,
      /** @type {boolean} */ ended,
    ) => {
      this.dispatch({ type: 'projection', projection });
      this.report('view', ended);
    };
    /** @internal the Klein view beside the 3D view (the split view) */
    this.kleinPane = new KleinPane(els, { i18n, mark, steer, say, insets: (canvas) => covered(els, canvas) });
    /** @internal the line marked in both views, drawn in the 3D view */
    this.lineMark = new LineMark(els, { viewer: this.viewer, mark });
    /** @internal choosing by pointing where the scene offers it (the Klein scene's marked ruling) */
    this.scenePick = new ScenePick(els, {
      viewer: this.viewer,
      set: (key, value) => {
        this.setParam(key, value);
        // (the parameter's change forgets the mark of the view beside: the same line, marked again there)
        if (this.state.view === 'split') mark(value);
      },
    });
    /** @internal */
    this.edit = new EditHost({
      els,
      viewer: this.viewer,
      state,
      built: () => this.session.built,
      i18n,
      apply: (input, ended, said) => this.setInput(input, ended, said),
      say,
      asData: options.onEditAsData ?? null,
    });
    /** @internal */
    this.shortcuts = new Shortcuts(els, {
      host,
      page: !!options.page,
      i18n,
      edit: {
        active: () => this.editor.active,
        editing: () => this.editor.editing,
        toggle: () => this.editor.setEditing(!this.editor.editing),
        undo: () => this.editor.undo(),
        redo: () => this.editor.redo(),
      },
      reset: () => this.reset(),
      play: () => {
        const key = this.player.playableKey();
        if (key) this.player.toggle(key);
      },
      step: () => this.player.step(),
      describe: () => say(this.results.spoken()),
    });
    // (turning the view changes no number: the readout is not said again)
    this.viewer.onCameraChange = (ended) => this.report('camera', ended);
    wireToolbar(els, {
      fit: () => {
        this.viewer.fit();
        this.report('camera', true);
      },
      reset: () => this.reset(),
      fullscreen: () => this.toggleFullscreen(),
      // (the reader's choice: the page writes it into its link)
      klein: () => {
        this.setView(this.state.view === 'split' ? 'space' : 'split');
        this.report('view', true);
      },
      help: () => this.shortcuts.open(),
      cancel: () => {
        this.session.cancel();
        // a long job in the worker (a tool path's post) stops there too
        cancelWork();
      },
    });
    els.buttons.klein.setAttribute('aria-pressed', String(this.state.view === 'split'));
    /** @internal how the stage is arranged for its box (stage/layout.js) */
    this.layout = {
      host,
      page: !!options.page,
      controls: () => this.state.controls,
      fitControls: () => this.controls?.fit(),
      redraw: () => this.viewer.requestRender(),
    };
    /** @internal */
    this.resize = new ResizeObserver(() => arrange(els, this.layout));
    this.resize.observe(els.root);
    this.showPanel(this.state);
    this.localize();
  }

  /**
   * @internal Draws a change of the state: the core asked for what the state shows where what
   * it computes from changed (an opening computes in its own steps: stage/open.js), then each
   * part from the state (and what the core built).
   * @param {import('./store.js').StageState} next
   * @param {import('./store.js').StageState} previous
   * @param {import('./store.js').StageChange} change
   */
  render(next, previous, change) {
    if (next.lang !== previous.lang) this.i18n = translator(next.lang);
    if (change.type === 'open') return;
    if (
      next.scene &&
      (next.params !== previous.params || next.input !== previous.input || next.data !== previous.data)
    ) {
      // (a choice that changes the figure's size frames it anew)
      const p = change.type === 'param' ? next.scene.params.find((q) => q.key === change.key) : undefined;
      this.compute({ fit: p?.type === 'select' && p.refit !== false });
    }
    this.show(next, previous);
  }

  /**
   * @internal Each part drawn from the state where what it draws from changed.
   * @param {import('./store.js').StageState} next
   * @param {import('./store.js').StageState | null} previous   null: everything
   */
  show(next, previous) {
    const changed = (/** @type {Array<keyof import('./store.js').StageState>} */ ...keys) =>
      !previous || keys.some((k) => next[k] !== previous[k]);
    if (changed('params', 'input', 'exercise')) this.controls?.update(next.params);
    if (changed('params', 'paper', 'exercise', 'scene', 'lang')) this.paperCard.render(next);
    if (changed('controls', 'text', 'exercise')) this.showPanel(next);
    if (changed('exercise', 'scene', 'input')) this.player.render(next);
    if (changed('view', 'lang', 'projection')) {
      this.els.buttons.klein.setAttribute('aria-pressed', String(next.view === 'split'));
      this.kleinPane.render(next, this.session.built);
    }
    if (changed('marked', 'view')) {
      this.kleinPane.showMark(next);
      this.lineMark.render(next, this.session.built);
    }
    this.edit.render(next, null);
  }

  /** @internal The panel: the controls and the explanation shown or not (an exercise may hide the explanation). */
  showPanel(/** @type {import('./store.js').StageState} */ state) {
    const { root, text: article, heading, panel } = this.els;
    const { controls, text } = state;
    root.classList.toggle('rl-no-controls', !controls);
    article.hidden = !text || !!state.exercise?.hide.includes('text');
    heading.hidden = !controls && !text;
    panel.hidden = !controls && !text;
    root.classList.toggle('rl-no-panel', !controls && !text);
    arrange(this.els, this.layout);
  }

  /** @internal The editor of the scene's handles. */
  get editor() {
    return this.edit.editor;
  }

  /** The state now (store.js): frozen, changed only by `dispatch`. */
  get state() {
    return this.store.state;
  }

  /**
   * @internal Changes the state (store.js's `dispatch`, its one writer).
   * @param {import('./store.js').StageChange} change
   */
  dispatch(change) {
    return this.store.dispatch(change);
  }

  /** The scene shown. @returns {import('./scene.js').Scene | null} */
  get scene() {
    return this.state.scene;
  }

  /** Its parameters. @returns {import('./scene.js').Params} */
  get params() {
    return this.state.params;
  }

  /** Your data (the "data" and milling scenes). @returns {import('./scene.js').ImportedData | null} */
  get data() {
    return this.state.data;
  }

  /** The figure of the paper shown, if any. @returns {import('./paper.js').PaperPreset | null} */
  get paper() {
    return this.state.paper;
  }

  /** The reader's edit of the scene's input (null: the built-in input). @returns {import('./scene.js').Input | null} */
  get input() {
    return this.state.input;
  }

  /** The i18n key of a note about the edit (too large for the link), or ''. */
  get inputNote() {
    return this.state.inputNote;
  }

  /** The exercise being done, if any. @returns {import('./task/format.js').Task | null} */
  get task() {
    return this.state.exercise;
  }

  /** @internal The parameter the reader changed last (an error names its field). */
  get lastChanged() {
    return this.state.changed;
  }

  /** @internal Whether the controls (and the readout) are shown. */
  get showControls() {
    return this.state.controls;
  }

  /** @internal Whether the explanation is shown. */
  get showText() {
    return this.state.text;
  }

  /** @internal Tells the stage's owner what changed (the page writes the link, the element fires events). */
  report(
    /** @type {'scene' | 'param' | 'camera' | 'lang' | 'reset' | 'input' | 'view'} */ reason,
    /** @type {boolean} */ ended,
  ) {
    this.options.onChange?.({ reason, ended });
  }

  /** @internal Announces the readout to screen readers (after `prefix`) once an interaction ends. */
  announce(prefix = '') {
    this.announcer.announce(prefix);
  }

  /** Shows notes about values that were not used (a link's, an element's, an exercise that could not open), in the view. */
  showNotes(/** @type {Notes} */ notes) {
    this.results.notes(notes);
  }

  /** Shows or hides the controls and the explanation. */
  setPanel(/** @type {boolean} */ controls, /** @type {boolean} */ text) {
    this.dispatch({ type: 'panel', controls, text });
  }

  /**
   * Shows the 3D view alone ("space") or the Klein view of the scene's lines beside it ("split").
   * @param {'space' | 'split'} view
   */
  setView(view) {
    this.dispatch({ type: 'view', view });
  }

  /** The 3D view alone ("space") or the Klein view beside it ("split"). @returns {'space' | 'split'} */
  get view() {
    return this.state.view;
  }

  /**
   * Draws the Klein view beside in `projection` (each number held in its range and on its step),
   * or in the scene's own image (null).
   * @param {{mix: number, turn: number, unit: number} | null} projection
   */
  setProjection(projection) {
    this.dispatch({ type: 'projection', projection });
  }

  /**
   * The image the Klein view beside draws in as the reader steered it, or null (the scene's own).
   * @returns {{mix: number, turn: number, unit: number} | null}
   */
  get projection() {
    return this.state.projection;
  }

  /**
   * The image the Klein view beside draws in now (the reader's, or the scene's own).
   * @returns {{mix: number, turn: number, unit: number}}
   */
  get kleinImage() {
    return this.kleinPane.image;
  }

  /** @internal The texts that depend on the language but not on the scene. */
  localize() {
    labelToolbar(this.els, this.i18n);
    this.kleinPane.localize(this.i18n.t);
    this.shortcuts.localize();
    this.edit.localize();
  }

  /** Whether the reader may drag the scene's handles. */
  setEditable(/** @type {boolean} */ on) {
    this.dispatch({ type: 'editable', on });
  }

  /**
   * Computes the scene on an edited input (null: the built-in one) — a handle was moved, a step
   * undone, the input replaced; `ended`: the step is over (the link is written, `change` fired).
   * @param {import('./scene.js').Input | null} input
   * @param {boolean} ended
   * @param {string | (() => string)} [said]   what the step did, said before the readout once it
   *   has ended (a function: asked once the scene is computed on the input)
   */
  setInput(input, ended, said = '') {
    if (!this.scene) return;
    const changed = this.dispatch({ type: 'input', input: input ? copyInput(input) : null, moving: !ended });
    // (the same input that ends a move: the figure computed on it is shown whole now)
    if (!changed) this.compute();
    this.report('input', ended);
    if (ended) this.announce(typeof said === 'function' ? said() : said);
  }

  /** Sets the note about the edit (an i18n key, or ''): the page's "kept in this tab". */
  setInputNote(/** @type {string} */ note) {
    this.dispatch({ type: 'inputNote', note });
  }

  /**
   * Opens an exercise (task/format.js): its scene at its start, what it lets change (the rest
   * held), what it hides; `state` restores a reader's progress (parameters the exercise lets
   * change, an edit where handles may move). null leaves the exercise (the scene stays).
   * (stage/open.js's openView opens it, as it opens everything.)
   * @param {import('./task/format.js').Task | null} task
   * @param {import('./scene.js').Scene | null} [_scene]   unused: the exercise names its scene
   * @param {{params?: import('./scene.js').Params, input?: import('./scene.js').Input | null, camera?: number[] | null, notes?: Notes, attempt?: import('./task/attempt.js').Attempt | null}} [state]
   */
  async openTask(task, _scene = null, state = {}) {
    if (!task) return leaveExercise(this);
    await openView(this, {
      task: task.drawn?.from ?? task,
      seed: task.drawn?.seed ?? null,
      progress: () => state.params ?? {},
      taskInput: state.input ?? null,
      camera: state.camera ?? null,
      notes: state.notes,
      attempt: state.attempt ?? null,
    });
  }

  /** Leaves the exercise shown (if any): the scene stays as it is, with nothing held. */
  leaveExercise() {
    leaveExercise(this);
  }

  /** Back to the exercise's start (its parameters and edit). */
  startTask() {
    this.exercise.start();
  }

  /** The exercise's solution state (its parameters and edit) on screen. */
  solveTask() {
    this.exercise.solve();
  }

  /** The current input of the scene's handles (the edit, or the built-in input), copied; null without handles. */
  currentInput() {
    const sets = this.session.built?.input?.sets;
    if (this.input) return copyInput(this.input);
    return sets?.length ? inputOf(sets) : null;
  }

  /** The language (a code of i18n/index.js, or null for the browser's). */
  setLanguage(/** @type {string | null} */ lang) {
    this.i18n = translator(pickLanguage(lang));
    this.dispatch({ type: 'lang', lang: this.i18n.lang });
    this.localize();
    if (!this.scene) return;
    this.enter(this.scene, this.params, {
      camera: this.viewer.camera.toArray(),
      fit: false,
      input: this.input,
      history: true,
    });
    // (a computation that fails keeps the last picture: its legend speaks the new language too)
    showLegend(this.els.legend, this.scene, this.params, this.i18n.t, this.session.built);
    this.exercise.panel.render();
  }

  /**
   * Opens a scene with `params` (missing ones take their defaults), leaving an exercise shown;
   * resolves to whether it is shown (false where an opening begun meanwhile took the stage).
   * @param {import('./scene.js').Scene} scene
   * @param {import('./scene.js').Params} params
   * @param {OpenOptions} [options]
   */
  async open(scene, params, options = {}) {
    await openView(this, { scene, params, ...options });
    return this.scene === scene;
  }

  /**
   * Shows the heading and the explanation of `scene` before it can be opened (the core still
   * loading): the reader reads while the figure is on its way. open() shows them again.
   * @param {import('./scene.js').Scene} scene
   */
  preview(scene) {
    const { heading, text } = this.els;
    const { t } = this.i18n;
    heading.textContent = '';
    appendRich(heading, t(scene.title));
    // the explanation is markup from the project's own language files (never user text)
    text.innerHTML = t(scene.text);
    // (its display equations: tab stops where they scroll)
    watchMath(text);
  }

  /**
   * @internal Shows `scene` with `params` (stage/open.js's enterScene); returns whether the
   * input given (if any) fits the scene's handles.
   * @param {import('./scene.js').Scene} scene
   * @param {import('./scene.js').Params} params
   * @param {import('./stage/open.js').EnterOptions} options
   */
  enter(scene, params, options) {
    return enterScene(this, scene, params, options);
  }

  /**
   * Why parameter `key` is held where it is (an i18n key), or null: an exercise holds what it
   * does not let change, an edit of the input holds what would replace it. A held parameter
   * changes by no route — slider, − / +, its field, play, single step, setParam.
   */
  heldReason(/** @type {string} */ key) {
    return heldReason(this.state, key);
  }

  /** Sets one parameter and recomputes (not one that is held: heldReason). */
  setParam(/** @type {string} */ key, /** @type {number | string | boolean} */ value, ended = true) {
    if (this.heldReason(key)) return;
    if (!this.scene || this.params[key] === value) {
      if (ended) {
        this.report('param', true);
        this.announce();
      }
      return;
    }
    this.dispatch({ type: 'param', key, value });
    this.report('param', ended);
    if (ended) this.announce();
  }

  /**
   * @internal Where the keyboard goes when the button it was on is gone with what it did: the
   * first control that takes it, else the view.
   */
  keepKeyboard() {
    const first = /** @type {HTMLElement | null} */ (this.els.form.querySelector('[name]:not(:disabled)'));
    (first && first.offsetParent !== null ? first : this.els.canvas).focus({ preventScroll: true });
  }

  /** @internal Back to the settings of the paper's figure shown (its card's button). */
  backToPaper() {
    const { scene, paper } = this;
    if (!scene || !paper) return;
    this.player.stop();
    this.enter(scene, { ...defaults(scene), ...paper.params }, { fit: true });
    this.report('param', true);
    this.announce();
    // the button is gone with the change: keep the keyboard in the controls
    this.keepKeyboard();
  }

  /** @internal What a scene's create() is given besides its parameters, now. */
  context() {
    return {
      t: this.i18n.t,
      format: this.i18n.format,
      lang: this.i18n.lang,
      data: this.data ?? undefined,
      refine: refineInWorker,
      invariants: invariantsInWorker,
      input: this.input ?? undefined,
    };
  }

  /** @internal Recomputes the scene for the current state; returns what it built, or null. */
  compute({ fit = false } = {}) {
    if (!this.scene) return null;
    const built = this.session.show(this.scene, this.params, this.context(), { fit });
    this.els.root.classList.toggle('rl-stale', !built);
    if (built) this.els.error.hidden = true;
    return built;
  }

  /**
   * @internal Shows an error in the view (and next to the control it concerns), in the view's
   * language; the last picture stays. Returns the sentence shown.
   */
  fail(/** @type {unknown} */ e) {
    return this.results.fail(this.state, e);
  }

  /** The scene's defaults and its fitted camera (in an exercise: its start; with an edit: the built-in input, undoably). */
  reset() {
    if (!this.scene) return;
    if (this.task) {
      // as Start over: the answers go, the attempt's checks and a solution shown stay
      this.exercise.panel.show(this.task, { checks: this.exercise.panel.checks, shown: this.exercise.panel.shown });
      return this.startTask();
    }
    this.player.stop();
    // an edit is taken back first, as one step of undo (↶ brings it back); pressed again, Reset
    // resets the controls
    if (this.input && this.editor.enabled) {
      this.editor.restore();
      this.viewer.fit();
      return;
    }
    this.enter(this.scene, defaults(this.scene), { fit: true });
    this.report('reset', true);
    this.announce();
  }

  /** Fullscreen for the whole stage (view and panel), or back. */
  toggleFullscreen() {
    const doc = this.els.root.ownerDocument;
    if (doc.fullscreenElement) doc.exitFullscreen?.();
    else this.els.root.requestFullscreen?.().catch(() => {});
  }

  /** Releases the GL context, the worker's pending work and every listener. */
  dispose() {
    this.player.stop();
    this.announcer.dispose();
    this.editor.dispose();
    this.session.dispose();
    this.viewer.dispose();
    this.kleinPane.close();
    this.resize.disconnect();
    this.shortcuts.dispose();
    this.els.root.remove();
  }
}
