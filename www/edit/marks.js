// The handles of an edit as the reader sees and hears them: rings drawn over the view (every one
// while editing; else the one under the pointer or dragged), the selected one marked; the tip
// beside a handle with its coordinates (a long press, a drag); and a handle in words ("ruling 5,
// end b: 1.20, −0.40, 3.00"), said at most once a second while it moves.
import { toScreen } from './geometry.js';

/** Least time between two announcements of a moving handle (ms). */
const SAY_EVERY = 1000;

export class HandleMarks {
  /** @param {import('./editor.js').Editor} editor */
  constructor(editor) {
    this.editor = editor;
    const doc = editor.view.ownerDocument;
    this.layer = Object.assign(doc.createElement('div'), { className: 'rl-handles' });
    this.layer.setAttribute('aria-hidden', 'true');
    this.tip = Object.assign(doc.createElement('div'), { className: 'rl-handle-tip', hidden: true });
    this.layer.append(this.tip);
    editor.view.append(this.layer);
    /** @type {HTMLElement[]} */
    this.rings = [];
    this.lastSaid = 0;
    this.sayTimer = 0;
  }

  /** A handle in words: "ruling 5, end b: 1.20, −0.40, 3.00". */
  describe(/** @type {number} */ k) {
    const handle = this.editor.handles()[k];
    if (!handle) return '';
    const i18n = this.editor.hooks.i18n();
    return `${this.nameOf(handle)}: ${coordinates(handle.point, i18n.lang)}`;
  }

  /** The name of a handle ("ruling 5, end b"). */
  nameOf(/** @type {import('./editor.js').Handle} */ handle) {
    const { t } = this.editor.hooks.i18n();
    const set = this.editor.sets[handle.set];
    const line = set.shape === 'pairs' ? handle.index >> 1 : handle.index;
    const end = set.ends ? t(set.ends[handle.index & 1]) : '';
    /** @type {Record<string, string>} */
    const vars = { i: String(line), end };
    if (set.cols) Object.assign(vars, { row: String(Math.floor(line / set.cols)), col: String(line % set.cols) });
    return t(set.name, vars);
  }

  /** Says where handle `k` is, at most once a second (the last position wins). */
  sayLater(/** @type {number} */ k) {
    clearTimeout(this.sayTimer);
    const wait = this.lastSaid + SAY_EVERY - performance.now();
    const say = () => {
      this.lastSaid = performance.now();
      this.editor.hooks.say(this.describe(k));
    };
    if (wait <= 0) say();
    else this.sayTimer = window.setTimeout(say, wait);
  }

  /** Says nothing more of a handle that has stopped (its last words are said by the stage). */
  quiet() {
    clearTimeout(this.sayTimer);
  }

  /** Shows the coordinates of handle `k` beside it. */
  showTip(/** @type {number} */ k) {
    this.tip.textContent = this.describe(k);
    this.tip.hidden = false;
    this.tip.dataset.handle = String(k);
    this.editor.viewer.requestRender();
  }

  hideTip() {
    this.tip.hidden = true;
  }

  /**
   * Draws the handles over the view after a frame (every one while editing; else the one under
   * the pointer or dragged), the selected one marked.
   * @param {ArrayLike<number>} viewProj
   */
  place(viewProj) {
    const editor = this.editor;
    const doc = this.layer.ownerDocument;
    const { clientWidth: w, clientHeight: h } = editor.viewer.canvas;
    const all = editor.active ? editor.handles() : [];
    const dragged = editor.drag?.handle ?? -1;
    const shown = all
      .map((handle, k) => ({ handle, k }))
      .filter(({ k }) => editor.editing || k === editor.hover || k === dragged);
    while (this.rings.length < shown.length) {
      const ring = Object.assign(doc.createElement('span'), { className: 'rl-handle' });
      this.layer.append(ring);
      this.rings.push(ring);
    }
    this.rings.forEach((ring, i) => {
      const item = shown[i];
      if (!item) {
        ring.hidden = true;
        return;
      }
      const s = toScreen(viewProj, item.handle.world, w, h);
      ring.hidden = !s.visible;
      ring.style.transform = `translate(${s.x}px, ${s.y}px)`;
      ring.classList.toggle('rl-hover', item.k === editor.hover || item.k === dragged);
      ring.classList.toggle('rl-selected', editor.editing && item.k === editor.selected);
      ring.dataset.handle = String(item.k);
    });
    if (!this.tip.hidden) {
      const handle = all[Number(this.tip.dataset.handle)];
      if (handle) {
        const s = toScreen(viewProj, handle.world, w, h);
        this.tip.style.transform = `translate(${Math.min(s.x + 14, w - this.tip.offsetWidth - 4)}px, ${Math.max(4, s.y - 34)}px)`;
      }
    }
  }

  dispose() {
    clearTimeout(this.sayTimer);
    this.layer.remove();
  }
}

/** Coordinates as the language writes them: "1.20, −0.40, 3.00" (German: "1,20; −0,40; 3,00"). */
export function coordinates(/** @type {number[]} */ p, /** @type {string} */ lang) {
  const f = new Intl.NumberFormat(lang, { minimumFractionDigits: 2, maximumFractionDigits: 2, useGrouping: false });
  return p.map((x) => f.format(Math.abs(x) < 0.005 ? 0 : x).replace('-', '−')).join(lang === 'de' ? '; ' : ', ');
}
