// <ruled-view>: one ruledlab scene as a custom element, for embedding in any page.
//
//   <script type="module" src="…/www/ruled-view.js"></script>
//   <ruled-view scene="isometry" params="surface=helical&t=0.5" style="height: 400px"></ruled-view>
//
// Attributes (also properties): `scene` (a scene id: striction, notation, convergence, isometry,
// curves, strip, congruence, milling, lines, large, data) and `params` (the scene's parameters as
// a query string; omitted ones take their defaults). The property `data` ({ segments:
// Float64Array, rows?, cols? }, e.g. from importSegments) shows your own rulings or congruence
// (it selects the "data" scene). Several instances may share a page; each has
// its own WebGL context and camera. Events: `scene-change` (detail: { scene, params }) after
// every rebuild, `view-change` (detail: { yaw, pitch, distance, target }) when the camera moves.
import init from '../pkg/ruledlab.js';
import { Viewer } from './viewer.js';
import { SCENES } from './scenes/index.js';
import { COLORS, css } from './theme.js';

let ready = null;
/** Loads the wasm module once for every element on the page. */
function loadWasm() {
  ready ??= init({ module_or_path: new URL('../pkg/ruledlab_bg.wasm', import.meta.url) });
  return ready;
}

const STYLE = `
:host { display: block; position: relative; min-height: 240px; background: #fbfaf7; font: 13px system-ui, sans-serif; color: #1d2435; }
canvas { width: 100%; height: 100%; display: block; outline: none; touch-action: none; position: absolute; inset: 0; }
.legend { position: absolute; left: .5rem; top: .4rem; margin: 0; padding: .3rem .5rem; list-style: none; background: rgb(255 255 255 / .85); border-radius: 5px; font-size: 12px; }
.legend li { display: flex; align-items: center; gap: .4rem; }
.legend span.swatch { width: 1.2rem; height: .25rem; border-radius: 2px; }
.error { position: absolute; inset: auto .5rem .5rem .5rem; background: #fff0f0; color: #8a1111; padding: .4rem; border-radius: 5px; }
.labels { position: absolute; inset: 0; pointer-events: none; overflow: hidden; }
.label { position: absolute; left: 0; top: 0; font: italic 14px serif; margin: -9px 0 0 6px; }
`;

export class RuledView extends HTMLElement {
  static observedAttributes = ['scene', 'params'];

  constructor() {
    super();
    const root = this.attachShadow({ mode: 'open' });
    root.innerHTML = `<style>${STYLE}</style><canvas tabindex="0" aria-label="3D view"></canvas><ul class="legend"></ul><p class="error" hidden></p>`;
    this.canvas = root.querySelector('canvas');
    this.viewer = null;
  }

  get scene() {
    return this.getAttribute('scene') ?? SCENES[0].id;
  }
  set scene(id) {
    this.setAttribute('scene', id);
  }
  /** Your own segments: { segments: Float64Array (6 per line), rows?, cols? }. */
  get data() {
    return this._data ?? null;
  }
  set data(value) {
    this._data = value;
    if (this.scene !== 'data') this.scene = 'data';
    else if (this.viewer) this.rebuild(true);
  }

  get params() {
    return this.getAttribute('params') ?? '';
  }
  set params(query) {
    this.setAttribute('params', query);
  }

  async connectedCallback() {
    await loadWasm();
    if (!this.viewer) {
      this.viewer = new Viewer(this.canvas);
      this.viewer.onCameraChange = () => {
        const { yaw, pitch, distance, target } = this.viewer.camera;
        this.dispatchEvent(new CustomEvent('view-change', { detail: { yaw, pitch, distance, target } }));
      };
      this.viewer.onFrame = (n) => (this.dataset.frames = String(n));
    }
    this.rebuild(true);
  }

  attributeChangedCallback(name, before, after) {
    if (this.viewer && before !== after) this.rebuild(name === 'scene');
  }

  /** Recomputes the scene from the attributes; an unknown scene or bad parameter is shown, not thrown. */
  rebuild(fit) {
    const error = this.shadowRoot.querySelector('.error');
    try {
      const scene = SCENES.find((s) => s.id === this.scene);
      if (!scene) throw new Error(`unknown scene "${this.scene}"; known: ${SCENES.map((s) => s.id).join(', ')}`);
      const q = new URLSearchParams(this.params);
      const params = {};
      for (const p of scene.params) {
        const raw = q.get(p.key);
        params[p.key] = raw === null ? p.value : p.type === 'checkbox' ? raw === '1' || raw === 'true' : p.type === 'range' ? Math.min(p.max, Math.max(p.min, Number(raw))) : raw;
      }
      const built = scene.id === 'data' && this._data ? scene.create(params, this._data) : scene.create(params);
      this.viewer.setScene(built, { fit });
      built.later?.(() => {}).then((done) => this.viewer.setScene(done)).catch(() => {});
      this.shadowRoot.querySelector('.legend').replaceChildren(
        ...scene.legend
          .filter(([, , when]) => !when || (typeof when === 'function' ? when(params) : params[when]))
          .map(([color, html]) => {
            const li = document.createElement('li');
            const sw = document.createElement('span');
            sw.className = 'swatch';
            sw.style.background = css(COLORS[color]);
            const label = document.createElement('span');
            label.innerHTML = html;
            li.append(sw, label);
            return li;
          }),
      );
      error.hidden = true;
      this.dispatchEvent(new CustomEvent('scene-change', { detail: { scene: scene.id, params } }));
    } catch (e) {
      error.hidden = false;
      error.textContent = String(e.message ?? e);
    }
  }
}

customElements.define('ruled-view', RuledView);
