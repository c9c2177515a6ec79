// <ruled-view>: one ruledlab scene as a custom element, for any web page.
//
//   <script type="module" src="…/www/view.js"></script>     (or: import 'ruledlab/view')
//   <ruled-view scene="isometry" params="surface=helical&t=0.5" controls lang="de"></ruled-view>
//
// Attributes (also properties): `scene` (a scene id), `params` (its parameters as a query
// string; omitted ones take their defaults), `paper` (a figure or example of the paper, e.g.
// "fig15" or "ex3": its scene with the paper's settings and the card saying what the paper shows
// and where ruledlab differs; `params` still override), `controls` (show the sliders, menus, checkboxes and
// the readout, beside or below the view as the element's width allows), `text` (the
// explanation too), `autoplay` (play the first playable parameter, unless the reader prefers
// reduced motion), `lang` ("en" or "de"; default: the page's language, then the browser's),
// `camera` (yaw, pitch, distance, target x, y, z: the page's `cam` link value), `editable` (the
// reader may drag the scene's handles: rulings' endpoints, grid points, tool poses, control
// points), `input` (an edit of those handles: the page's `input` link value). The property
// `data` is the scene's input, `{ set: Float64Array, … }` per handle set (a copy; setting it
// replaces the input); set to `{ segments: Float64Array, rows?, cols? }` it shows your own
// rulings or congruence in the "data" scene. `height` sizes the element (pixels or a CSS length,
// without an inline style a strict Content-Security-Policy would refuse), `klein` (the scene's
// lines as points of the Klein quadric, beside the 3D view; the toolbar's Klein quadric button
// sets and clears it; its value "α,β,ℓ" the image it is drawn in, written back when the reader
// lets go of the view's sliders; empty: the scene's own image). `handles()` lists every handle with its position
// in the element. `task` shows an exercise (a built-in one's id, or the page's "j." link value;
// the book's "Exercises"), `seed` the seed of its drawn numbers, `leave` offers to leave it,
// `solution` says when its solution is offered ("never", or after how many checks that did not
// solve it; default 1); `task-check` and `task-solved` report how it stands, `task-solution` that
// the solution was shown (it counts for nothing, nor does a check after it: `counted` false; also
// posted to the parent window of a frame), `exercise` lets a program check, show the solution, start over. Events: `input` during a drag and `change` at its end (detail: { scene, data,
// readouts }), `scene-change` (detail: { scene, params }), `view-change` (detail: the
// camera, during a move), `camera-change` (detail: { camera, yaw, pitch, distance, target },
// once a move ends; `camera` is the attribute's value), `error` (detail: { message, code },
// the message in the element's language, also shown in the element). The element starts the
// wasm core before it reads anything that needs it, so it works as the first ruledlab code on
// a page. Disconnecting the element releases its WebGL context and every wasm object it made.
import { Stage } from './stage.js';
import { DEFAULT_SOLUTION_RULE, readSolutionRule } from './task/solution-rule.js';
import { MAX_SOLUTION_AFTER } from './limits.js';
import { SCENES } from './scenes/index.js';
import { readParams, readSome, defaults } from './scene.js';
import { readCamera, writeCamera } from './link.js';
import { readProjection, writeProjection } from './klein-projection.js';
import { decodeInput, encodeInput, fitsSets, linkableInput } from './edit/input.js';
import { toScreen } from './edit/geometry.js';
import { plainRich } from './ui/richtext.js';
import { postToParent } from './task/message.js';
import { openView } from './stage/open.js';
import { exerciseApi } from './stage/exercise-api.js';
import { linkSeed } from './task/format.js';
import { start } from './core.js';
import { translator, pickLanguage } from './i18n/index.js';
import { startFailure } from './ui/errors.js';
import { append } from './reduce.js';
import { showFailure } from './ui/failure.js';
import { PRESETS, findPreset, withPreset } from './paper.js';
import { adoptStyles } from './ui/css.js';
import { exportSvg } from './export/svg.js';
import { exportTikz } from './export/tikz.js';
import { png } from './export/png.js';

// the element is a box of its own size: the view and its controls stay inside it at every width
// (beside each other when there is room, the panel under the view and scrolling inside the box
// otherwise: ui/css.js)
const HOST_CSS = `:host { display: block; position: relative; max-width: 100%; height: 480px; min-height: 240px; overflow: hidden; contain: content; }
:host([hidden]) { display: none; }
.rl-failed { margin: 1rem; padding: .8rem 1rem; color: #5a1a12; background: #fff3ef; border: 1px solid #e6b2aa; border-radius: 8px; font: 15px/1.45 system-ui, sans-serif; }
.rl-host { width: 100%; height: 100%; }`;

let hostSheet = /** @type {CSSStyleSheet | null} */ (null);

/**
 * @typedef {import('./ruled-view-events.js').SceneChangeDetail} SceneChangeDetail
 * @typedef {import('./ruled-view-events.js').RuledViewEventMap} RuledViewEventMap
 * @typedef {import('./ruled-view-events.js').HandleInfo} HandleInfo
 * @typedef {import('./ruled-view-events.js').EditDetail} EditDetail
 */

export class RuledView extends HTMLElement {
  static observedAttributes = [
    'scene',
    'paper',
    'params',
    'controls',
    'text',
    'autoplay',
    'lang',
    'camera',
    'editable',
    'input',
    'height',
    'task',
    'seed',
    'leave',
    'solution',
    'klein',
  ];

  constructor() {
    super();
    const root = this.attachShadow({ mode: 'open' });
    adoptStyles(root);
    hostSheet ??= new CSSStyleSheet();
    if (!hostSheet.cssRules.length) hostSheet.replaceSync(HOST_CSS);
    root.adoptedStyleSheets = [...root.adoptedStyleSheets, hostSheet];
    /** @internal */
    this.container = Object.assign(document.createElement('div'), { className: 'rl-host' });
    root.append(this.container);
    // the controls' own input and change events stay inside: the element's are the reader's edits
    for (const type of ['input', 'change']) this.container.addEventListener(type, (e) => e.stopPropagation());
    /** @internal @type {Stage | null} */
    this.stage = null;
    /** @internal @type {import('./scene.js').ImportedData | null} */
    this._data = null;
    /** @internal */
    this.opening = Promise.resolve();
    /** @internal Counts open() calls: a later one supersedes an earlier one still starting the core. */
    this.openings = 0;
  }

  /**
   * Listens to an event of the element, typed by its name (`scene-change`, `view-change`,
   * `camera-change`, `error`: see RuledViewEventMap), or to any other event.
   * @template {keyof RuledViewEventMap} K
   * @overload
   * @param {K} type
   * @param {(this: RuledView, event: RuledViewEventMap[K]) => unknown} listener
   * @param {boolean | AddEventListenerOptions} [options]
   * @returns {void}
   */
  /**
   * @overload
   * @param {string} type
   * @param {EventListenerOrEventListenerObject} listener
   * @param {boolean | AddEventListenerOptions} [options]
   * @returns {void}
   */
  /**
   * @param {string} type
   * @param {any} listener
   * @param {boolean | AddEventListenerOptions} [options]
   */
  addEventListener(type, listener, options) {
    super.addEventListener(type, listener, options);
  }

  get scene() {
    return this.getAttribute('scene') ?? findPreset(this.paper)?.scene ?? SCENES[0].id;
  }
  set scene(id) {
    this.setAttribute('scene', String(id));
  }
  /** The figure or example of the paper shown (an id of PRESETS in paper.js), or "". */
  get paper() {
    return this.getAttribute('paper') ?? '';
  }
  set paper(id) {
    this.setAttribute('paper', String(id));
  }
  get params() {
    return this.getAttribute('params') ?? '';
  }
  set params(query) {
    this.setAttribute('params', String(query));
  }
  get controls() {
    return this.hasAttribute('controls');
  }
  set controls(on) {
    this.toggleAttribute('controls', !!on);
  }
  get text() {
    return this.hasAttribute('text');
  }
  set text(on) {
    this.toggleAttribute('text', !!on);
  }
  get autoplay() {
    return this.hasAttribute('autoplay');
  }
  set autoplay(on) {
    this.toggleAttribute('autoplay', !!on);
  }
  get lang() {
    return this.getAttribute('lang') ?? '';
  }
  set lang(code) {
    this.setAttribute('lang', String(code));
  }
  /** The camera as the attribute writes it ("yaw,pitch,distance,x,y,z"); the current one once shown. */
  get camera() {
    return this.stage?.scene ? writeCamera(this.stage.viewer.camera.toArray()) : (this.getAttribute('camera') ?? '');
  }
  set camera(value) {
    this.setAttribute('camera', String(value));
  }
  /**
   * The element's height: a number of CSS pixels ("560") or a CSS length ("70vh"); set through
   * the CSS object model, which a Content-Security-Policy without 'unsafe-inline' allows (a
   * `style` attribute it refuses).
   */
  get height() {
    return this.getAttribute('height') ?? '';
  }
  set height(value) {
    this.setAttribute('height', String(value));
  }

  /** @internal Applies the `height` attribute. */
  sized() {
    const h = (this.getAttribute('height') ?? '').trim();
    if (!h) return;
    const px = /^\d+(\.\d+)?$/.test(h) ? `${h}px` : h;
    if (CSS.supports('height', px)) this.style.height = px;
  }

  /** The exercise shown: a built-in one's id, or the page's link value ("j." and its JSON). */
  get task() {
    return this.getAttribute('task') ?? '';
  }
  set task(value) {
    this.setAttribute('task', String(value));
  }

  /** The seed of the exercise's drawn numbers (a whole number; none: one drawn when it opens). */
  get seed() {
    return this.getAttribute('seed') ?? '';
  }
  set seed(value) {
    this.setAttribute('seed', String(value));
  }

  /** The exercise shown, for a program (stage/exercise-api.js); null when none is shown. */
  get exercise() {
    return this.stage ? exerciseApi(this.stage) : null;
  }

  /**
   * Whether the Klein view of the scene's lines stands beside the 3D view (the attribute's value
   * "α,β,ℓ", the image it is drawn in, stays while it does).
   */
  get klein() {
    return this.hasAttribute('klein');
  }
  set klein(on) {
    this.toggleAttribute('klein', !!on);
  }
  /** Whether the reader may drag the scene's handles. */
  get editable() {
    return this.hasAttribute('editable');
  }
  set editable(on) {
    this.toggleAttribute('editable', !!on);
  }
  /** The edit of the scene's input as the attribute writes it (the link's `input` value); the current one once shown. */
  get input() {
    const input = this.stage?.input;
    return input && linkableInput(input) ? encodeInput(input) : (this.getAttribute('input') ?? '');
  }
  set input(value) {
    this.setAttribute('input', String(value));
  }

  /**
   * The scene's input, `{ set: Float64Array, … }` per handle set (a copy; null while nothing is
   * shown or the scene has no handles). Setting it replaces the input (one step of undo; the
   * sets and their lengths must be the scene's); setting `{ segments, rows?, cols? }` shows your
   * own rulings or congruence in the "data" scene.
   * @returns {import('./scene.js').Input | null}
   */
  get data() {
    return this.stage?.currentInput() ?? null;
  }
  /** @param {import('./scene.js').Input | import('./scene.js').ImportedData | null} value */
  set data(value) {
    if (value && 'segments' in value && value.segments instanceof Float64Array) {
      this._data = /** @type {import('./scene.js').ImportedData} */ (value);
      if (this.scene !== 'data') this.scene = 'data';
      else this.open();
      return;
    }
    const stage = this.stage;
    const sets = stage?.session.built?.input?.sets;
    const input = /** @type {import('./scene.js').Input | null} */ (value);
    if (!stage || !sets?.length)
      throw Object.assign(new Error('ruled-view: this scene has no input to set (or it is not shown yet)'), {
        code: 'invalid-argument',
      });
    if (!input || !fitsSets(input, sets) || !Object.values(input).every((v) => v.every(Number.isFinite)))
      throw Object.assign(
        new Error(
          `ruled-view: data must have the scene's sets, each a Float64Array of finite numbers as long as now: ${sets
            .map((s) => `${s.key} (${s.points.length})`)
            .join(', ')}`,
        ),
        { code: 'invalid-argument' },
      );
    stage.editor.replace(input);
  }

  /**
   * Every handle of the scene's input: its set, index, name, point and where it is drawn in the
   * element (CSS px).
   * @returns {HandleInfo[]}
   */
  handles() {
    const stage = this.stage;
    if (!stage) return [];
    const editor = stage.editor;
    const canvas = stage.viewer.canvas;
    const host = this.getBoundingClientRect();
    const view = canvas.getBoundingClientRect();
    const w = canvas.clientWidth || 1,
      h = canvas.clientHeight || 1;
    const m = stage.viewer.camera.viewProj(w / h);
    return editor.handles().map((handle) => {
      const s = toScreen(m, handle.world, w, h);
      return {
        set: handle.key,
        index: handle.index,
        name: editor.nameOf(handle),
        point: handle.point,
        x: view.left - host.left + s.x,
        y: view.top - host.top + s.y,
        visible: s.visible,
      };
    });
  }

  /** The Stage showing the scene (null while disconnected). */
  get view() {
    return this.stage;
  }

  /** @internal */
  connectedCallback() {
    this.sized();
    if (this.stage) return;
    const lang = this.getAttribute('lang') || this.closest('[lang]')?.getAttribute('lang') || null;
    try {
      this.start(lang);
    } catch (e) {
      // no view at all (no WebGL2 here): say so inside the element, never a blank box
      const box = Object.assign(document.createElement('p'), { className: 'rl-failed' });
      this.container.replaceChildren(box);
      const i18n = translator(pickLanguage(lang));
      showFailure(box, e, i18n);
      this.dispatchEvent(
        new CustomEvent('error', {
          detail: { message: startFailure(e, i18n).text, code: /** @type {any} */ (e)?.code ?? null, details: null },
        }),
      );
    }
  }

  /** @internal Makes the Stage of this element. */
  start(/** @type {string | null} */ lang) {
    this.stage = new Stage(this.container, {
      controls: this.controls,
      text: this.text,
      lang,
      editable: this.editable,
      view: this.klein ? 'split' : 'space',
      projection: readProjection(this.getAttribute('klein'))?.projection ?? null,
      // Leave, where the attribute allows it: the scene without the exercise
      onLeaveTask: () => this.stage?.leaveExercise(),
      mayLeaveTask: () => this.hasAttribute('leave'),
      solutionRule: () => readSolutionRule(this.getAttribute('solution')) ?? DEFAULT_SOLUTION_RULE,
      onEditAsData: (data) => {
        this.data = data;
      },
      onTask: (type, report) => {
        this.dispatchEvent(new CustomEvent(`task-${type}`, { detail: report }));
        const stage = this.stage;
        const input = stage?.input;
        postToParent(type, report, {
          scene: stage?.scene?.id ?? '',
          params: { ...(stage?.params ?? {}) },
          input: input ? encodeInput(input) : null,
        });
      },
      onChange: ({ reason, ended }) => {
        // the reader's choice of the view, in the attribute; its image when a slider is let go
        if (reason === 'view' && this.stage) {
          const { view, projection } = this.stage;
          if (view !== 'split') this.removeAttribute('klein');
          else if (ended) this.setAttribute('klein', projection ? writeProjection(projection) : '');
          else if (!this.klein) this.setAttribute('klein', '');
        }
        if (reason === 'input' && this.stage?.scene) {
          const stage = this.stage;
          const scene = this.stage.scene;
          const detail = { scene: scene.id, data: stage.currentInput() ?? {}, readouts: this.readouts() };
          this.dispatchEvent(new CustomEvent(ended ? 'change' : 'input', { detail }));
        }
        if (reason === 'camera' && this.stage) {
          const { yaw, pitch, distance, target } = this.stage.viewer.camera;
          const view = { yaw, pitch, distance, target: [...target] };
          this.dispatchEvent(new CustomEvent('view-change', { detail: view }));
          if (ended)
            this.dispatchEvent(
              new CustomEvent('camera-change', {
                detail: { camera: writeCamera(this.stage.viewer.camera.toArray()), ...view },
              }),
            );
        }
      },
      onBuilt: () => {
        if (!this.stage?.scene) return;
        this.dataset.ready = '1';
        this.dispatchEvent(
          new CustomEvent('scene-change', { detail: { scene: this.stage.scene.id, params: { ...this.stage.params } } }),
        );
      },
      onError: (e, message) => {
        const error = /** @type {any} */ (e);
        this.dispatchEvent(
          new CustomEvent('error', { detail: { message, code: error?.code ?? null, details: error?.details ?? null } }),
        );
      },
    });
    this.stage.viewer.onFrame = (n) => (this.dataset.frames = String(n));
    this.open();
  }

  /** @internal */
  disconnectedCallback() {
    this.stage?.dispose();
    this.stage = null;
    delete this.dataset.ready;
    delete this.dataset.frames;
  }

  /** @internal @param {string} name @param {string | null} before @param {string | null} after */
  attributeChangedCallback(name, before, after) {
    if (name === 'height') return this.sized();
    if (!this.stage || before === after) return;
    if (['scene', 'params', 'paper', 'task', 'seed'].includes(name)) this.open();
    else if (name === 'leave' || name === 'solution') this.stage.exercise.panel.render();
    else if (name === 'controls' || name === 'text') this.stage.setPanel(this.controls, this.text);
    else if (name === 'editable') this.stage.setEditable(this.editable);
    else if (name === 'klein') this.kleinChanged();
    else if (name === 'input') {
      // an edit of its own (the property read back) is already shown
      const now = this.stage.input;
      if (!(now && after === encodeInput(now))) this.open();
    } else if (name === 'lang') this.stage.setLanguage(after);
    else if (name === 'autoplay' && after !== null) this.open();
    else if (name === 'camera') {
      const camera = readCamera(after ?? '');
      if (camera && this.stage.scene) {
        this.stage.viewer.camera.fromArray(camera);
        this.stage.viewer.requestRender();
      }
    }
  }

  /**
   * Shows the scene of the attributes, once the core has started (reading a figure's
   * parameters needs it); an unknown scene or figure, or a core that cannot start, is shown in
   * the element in its language and fires `error`.
   * @internal
   */
  open() {
    const stage = this.stage;
    if (!stage) return this.opening;
    const mine = ++this.openings;
    this.opening = start()
      .then(
        () => {
          if (mine !== this.openings || this.stage !== stage) return;
          const { t } = stage.i18n;
          const scene = SCENES.find((s) => s.id === this.scene);
          if (!scene) {
            stage.fail(
              Object.assign(
                new Error(t('element.unknownScene', { scene: this.scene, known: SCENES.map((s) => s.id).join(', ') })),
                { code: 'invalid-argument', details: { option: 'scene' }, localized: true },
              ),
            );
            return;
          }
          const preset = findPreset(this.paper);
          if (this.paper && !preset) {
            stage.fail(
              Object.assign(
                new Error(t('element.unknownPaper', { paper: this.paper, known: PRESETS.map((p) => p.id).join(', ') })),
                { code: 'invalid-argument', details: { option: 'paper' }, localized: true },
              ),
            );
            return;
          }
          const paper = preset && preset.scene === scene.id ? preset : null;
          const query = new URLSearchParams(this.params);
          const read = readParams(scene, paper ? withPreset(paper, scene, query) : query);
          const { params } = read;
          // the values came from the element's params attribute, not from a link: said so
          /** @type {Array<{key: string, note: string, vars?: Record<string, string>}>} */
          const notes = read.notes.map((n) => ({ ...n, note: n.note.replace(/^note\./, 'element.note.') }));
          const camera = readCamera(this.getAttribute('camera') ?? '');
          if (this.hasAttribute('camera') && !camera) notes.push({ key: 'camera', note: 'element.badCamera' });
          const input = this.hasAttribute('input') ? decodeInput(this.getAttribute('input') ?? '') : null;
          if (this.hasAttribute('input') && !input) notes.push({ key: 'input', note: 'element.note.badInput' });
          const { seed, note } = linkSeed(this.getAttribute('seed'), 'element.note');
          if (note) notes.push(note);
          append(notes, this.kleinNotes());
          if (this.hasAttribute('solution') && !readSolutionRule(this.getAttribute('solution')))
            notes.push({
              key: 'solution',
              note: 'element.note.badSolution',
              vars: { max: String(MAX_SOLUTION_AFTER) },
            });
          // an exercise: its scene and start (the element's scene and params are its own then)
          return openView(stage, {
            scene,
            params: { ...defaults(scene), ...params },
            task: this.getAttribute('task') || null,
            seed,
            data: this._data,
            notes,
            autoplay: this.autoplay,
            paper,
            camera,
            input,
            source: 'element',
          }).then((shown) => this.refused(shown));
        },
        (e) => {
          // the core did not start: why, in the element's language
          stage.fail(
            Object.assign(new Error(startFailure(e, stage.i18n).text), {
              code: /** @type {any} */ (e)?.code,
              localized: true,
            }),
          );
        },
      )
      .catch(() => {});
    return this.opening;
  }

  /**
   * @internal The klein attribute drawn: the Klein view beside or not, in the image its value
   * gives (a value it cannot read, or one it holds in range, refused as a note).
   */
  kleinChanged() {
    const stage = this.stage;
    if (!stage) return;
    stage.setView(this.klein ? 'split' : 'space');
    if (!this.klein) return;
    const notes = this.kleinNotes();
    stage.setProjection(readProjection(this.getAttribute('klein'))?.projection ?? null);
    this.refused(notes);
  }

  /**
   * @internal What the klein attribute's value cannot give: a note for a value that is not three
   * numbers (the scene's own image is drawn), or for one outside its range (held there, and the
   * held value written back into the attribute).
   * @returns {Array<{key: string, note: string}>}
   */
  kleinNotes() {
    if (!this.klein) return [];
    const image = readProjection(this.getAttribute('klein'));
    if (image === undefined) return [{ key: 'klein', note: 'element.note.badKlein' }];
    if (!image.held || !image.projection) return [];
    this.setAttribute('klein', writeProjection(image.projection));
    return [{ key: 'klein', note: 'element.note.kleinHeld' }];
  }

  /**
   * @internal An attribute the element could not take (a value of `params`, `input`, `camera`,
   * `task`): shown as a note in the box, and an `error` event each, so that the page around can
   * tell — the scene is shown without it. `details.option` names the attribute.
   */
  refused(/** @type {Array<{key: string, note: string, vars?: Record<string, string>}>} */ notes) {
    const t = this.stage?.i18n.t;
    if (!t) return;
    for (const n of notes) {
      const option = ['camera', 'input', 'task', 'klein'].includes(n.key) ? n.key : 'params';
      this.dispatchEvent(
        new CustomEvent('error', {
          detail: {
            message: t(n.note, { key: n.key, ...n.vars }),
            code: 'invalid-argument',
            details: { option, reason: n.note, ...(option === 'params' ? { param: n.key } : {}) },
          },
        }),
      );
    }
  }

  /**
   * The numbers the readout shows now (an exercise's hidden ones too), as `change` gives them:
   * the label's i18n key, its text in the element's language, and the value (a number, or a word).
   * @returns {EditDetail['readouts']}
   */
  readouts() {
    const stage = this.stage;
    if (!stage) return [];
    const { t } = stage.i18n;
    return (stage.session.built?.readouts ?? []).map(({ label, value }) => {
      return { key: label, label: plainRich(t(label)), value: typeof value === 'number' ? value : t(String(value)) };
    });
  }

  /**
   * Sets the parameters named in `values` (an object, or a query string as `params` takes) as
   * the scene's controls would: the others, the camera and an edit stay. Values are read as the
   * `params` attribute's are; one the scene cannot take, or a name it has no parameter of, fires
   * `error` (`invalid-argument`, `details.param`). Returns the parameters now.
   * @param {Record<string, number | string | boolean> | string} values
   * @returns {import('./scene.js').Params}
   */
  setParams(values) {
    const stage = this.stage;
    if (!stage?.scene) throw Object.assign(new Error('ruled-view: no scene shown yet'), { code: 'invalid-argument' });
    const { params, notes } = readSome(stage.scene, values);
    for (const [key, value] of Object.entries(params)) stage.setParam(key, value);
    // (said as given to setParams, not as in the params attribute)
    this.refused(notes.map((n) => ({ ...n, note: n.note.replace(/^note\./, 'element.set.') })));
    return { ...stage.params };
  }

  /** The scene's defaults and its fitted view. */
  reset() {
    this.stage?.reset();
  }

  /**
   * The current view as a self-contained SVG 1.1 figure (labels as text), in colour or black
   * and white, the parts of lines a surface hides thin and dashed or left out, cropped to the
   * drawing and `width` cm wide on paper (lines, dashes and type keep their printed size):
   * `{ bw?, legend? = true, title? = false, labels? = true, hidden? = 'dashed' | 'omit', width? = 8 }`.
   * @param {import('./export/svg.js').FigureOptions} [options]
   */
  exportSVG(options) {
    if (!this.stage) throw Object.assign(new Error('ruled-view: not connected'), { code: 'invalid-argument' });
    return exportSvg(this.stage, options);
  }

  /** The current view as a TikZ picture for LaTeX (the same options as exportSVG: cropped, `width` cm wide). */
  exportTikZ(/** @type {import('./export/svg.js').FigureOptions & {width?: number}} */ options = {}) {
    if (!this.stage) throw Object.assign(new Error('ruled-view: not connected'), { code: 'invalid-argument' });
    return exportTikz(this.stage, options);
  }

  /** The current view as a PNG at `scale` (1, 2 or 4) × its size, labels and legend drawn in. */
  exportPNG(/** @type {{scale?: number, legend?: boolean}} */ options = {}) {
    if (!this.stage)
      return Promise.reject(Object.assign(new Error('ruled-view: not connected'), { code: 'invalid-argument' }));
    return png(this.stage, options);
  }
}

if (!customElements.get('ruled-view')) customElements.define('ruled-view', RuledView);
