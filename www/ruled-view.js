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
// `camera` (yaw, pitch, distance, target x, y, z: the page's `cam` link value). The
// property `data` ({ segments: Float64Array, rows?, cols? }) shows your own rulings or
// congruence. Events: `scene-change` (detail: { scene, params }), `view-change` (detail: the
// camera, during a move), `camera-change` (detail: { camera, yaw, pitch, distance, target },
// once a move ends; `camera` is the attribute's value), `error` (detail: { message, code },
// the message in the element's language, also shown in the element). The element starts the
// wasm core before it reads anything that needs it, so it works as the first ruledlab code on
// a page. Disconnecting the element releases its WebGL context and every wasm object it made.
import { Stage } from './stage.js';
import { SCENES } from './scenes/index.js';
import { readParams, defaults } from './scene.js';
import { readCamera, writeCamera } from './state.js';
import { start } from './core.js';
import { translator, pickLanguage } from './i18n/index.js';
import { startFailure } from './ui/errors.js';
import { showFailure } from './ui/failure.js';
import { PRESETS, findPreset, withPreset } from './paper.js';
import { adoptStyles } from './ui/css.js';
import { exportSvg } from './export/svg.js';
import { exportTikz } from './export/tikz.js';
import { png } from './export/png.js';

// the element is a box of its own size: the view and its controls stay inside it at every width
// (beside each other when there is room, the panel under the view and scrolling inside the box
// otherwise: ui/css.js)
const HOST_CSS = `:host { display: block; position: relative; height: 480px; min-height: 240px; overflow: hidden; contain: content; }
:host([hidden]) { display: none; }
.rl-failed { margin: 1rem; padding: .8rem 1rem; color: #5a1a12; background: #fff3ef; border: 1px solid #e6b2aa; border-radius: 8px; font: 15px/1.45 system-ui, sans-serif; }
.rl-host { width: 100%; height: 100%; }`;

let hostSheet = /** @type {CSSStyleSheet | null} */ (null);

/**
 * @typedef {object} SceneChangeDetail   `scene-change`: the scene shown and its parameters
 * @property {string} scene
 * @property {import('./scene.js').Params} params
 *
 * @typedef {object} ViewChangeDetail    `view-change`, during a camera move
 * @property {number} yaw
 * @property {number} pitch
 * @property {number} distance
 * @property {number[]} target
 *
 * @typedef {ViewChangeDetail & { camera: string }} CameraChangeDetail   `camera-change`, once a
 *   move ends: `camera` is the value of the element's `camera` attribute for this view
 *
 * @typedef {object} RuledViewErrorDetail   `error`: the message in the element's language
 * @property {string} message
 * @property {string | null} code           the error's stable code (README, "Errors")
 * @property {object | null} details        the core's details (reason, args, option, …)
 *
 * @typedef {object} RuledViewEvents       the events of <ruled-view> and their details
 * @property {CustomEvent<SceneChangeDetail>} scene-change
 * @property {CustomEvent<ViewChangeDetail>} view-change
 * @property {CustomEvent<CameraChangeDetail>} camera-change
 * @property {CustomEvent<RuledViewErrorDetail>} error
 *
 * @typedef {Omit<HTMLElementEventMap, 'error'> & RuledViewEvents} RuledViewEventMap
 */

export class RuledView extends HTMLElement {
  static observedAttributes = ['scene', 'paper', 'params', 'controls', 'text', 'autoplay', 'lang', 'camera'];

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
  /** Your own segments: { segments: Float64Array (6 per line), rows?, cols? }; selects the "data" scene. */
  get data() {
    return this._data;
  }
  set data(value) {
    this._data = value;
    if (this.scene !== 'data') this.scene = 'data';
    else this.open();
  }

  /** The Stage showing the scene (null while disconnected). */
  get view() {
    return this.stage;
  }

  /** @internal */
  connectedCallback() {
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
      onChange: ({ reason, ended }) => {
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
    if (!this.stage || before === after) return;
    if (name === 'scene' || name === 'params' || name === 'paper') this.open();
    else if (name === 'controls' || name === 'text') this.stage.setPanel(this.controls, this.text);
    else if (name === 'lang') this.stage.setLanguage(after);
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
          const { params, notes } = readParams(scene, paper ? withPreset(paper, scene, query) : query);
          const camera = readCamera(this.getAttribute('camera') ?? '');
          if (this.hasAttribute('camera') && !camera) notes.push({ key: 'camera', note: 'element.badCamera' });
          return stage.open(
            scene,
            { ...defaults(scene), ...params },
            { data: this._data, notes, autoplay: this.autoplay, paper, camera },
          );
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

  /** The scene's defaults and its fitted view. */
  reset() {
    this.stage?.reset();
  }

  /**
   * The current view as a self-contained SVG 1.1 figure (labels as text), in colour or black
   * and white, the parts of lines a surface hides thin and dashed or left out:
   * `{ bw?, legend? = true, title? = false, labels? = true, hidden? = 'dashed' | 'omit' }`.
   * @param {import('./export/svg.js').FigureOptions} [options]
   */
  exportSVG(options) {
    if (!this.stage) throw Object.assign(new Error('ruled-view: not connected'), { code: 'invalid-argument' });
    return exportSvg(this.stage, options);
  }

  /** The current view as a TikZ picture for LaTeX (same options as exportSVG, and `width` in cm). */
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
