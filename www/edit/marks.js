// The handles of an edit as the reader sees and hears them: rings drawn over the view (every one
// while editing; else the one under the pointer, dragged, or chosen), the selected one marked; a
// mark where a drag snapped, with the word for what it snapped onto; the tip beside a handle with
// its coordinates and the values of its neighbourhood (edit/values.js: a long press, a drag, a
// tap); and a handle in words ("ruling 5, end b: 1.20, −0.40, 3.00"), said at most once a second
// while it moves.
import { toScreen } from './geometry.js';
import { appendRich, plainRich } from '../ui/richtext.js';
import { FINE_DRAG } from '../limits.js';
import { append } from '../reduce.js';

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
    this.snapMark = Object.assign(doc.createElement('span'), { className: 'rl-snap-mark', hidden: true });
    this.layer.append(this.snapMark, this.tip);
    editor.view.append(this.layer);
    /** @type {HTMLElement[]} */
    this.rings = [];
    this.lastSaid = 0;
    this.sayTimer = 0;
    /** whether the tip's words wait for the next frame */
    this.stale = false;
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

  /** Handle `k` and its live values in words (what the tip shows). */
  spoken(/** @type {number} */ k) {
    const lines = this.editor.live.lines(k).map((l) => `${plainRich(l.label)}: ${l.text}`);
    return [this.describe(k), ...lines].join('; ');
  }

  /** Says where handle `k` is and its values, at most once a second (the last position wins). */
  sayLater(/** @type {number} */ k) {
    clearTimeout(this.sayTimer);
    const wait = this.lastSaid + SAY_EVERY - performance.now();
    const say = () => {
      this.lastSaid = performance.now();
      this.editor.hooks.say(this.spoken(k));
    };
    if (wait <= 0) say();
    else this.sayTimer = window.setTimeout(say, wait);
  }

  /** Says `text` now (a snap: it matters at once), holding the next position back a second. */
  sayNow(/** @type {string} */ text) {
    clearTimeout(this.sayTimer);
    this.lastSaid = performance.now();
    this.editor.hooks.say(text);
  }

  /** Says nothing more of a handle that has stopped (its last words are said by the stage). */
  quiet() {
    clearTimeout(this.sayTimer);
  }

  /**
   * Shows beside handle `k` its coordinates, what a move snapped it onto and its live values —
   * written once per frame, when the handles are placed (a pointer moves more often than that).
   */
  showTip(/** @type {number} */ k) {
    this.tip.hidden = false;
    this.tip.dataset.handle = String(k);
    this.stale = true;
    this.editor.viewer.requestRender();
  }

  /** @internal Writes the tip of handle `k`. */
  fillTip(/** @type {number} */ k) {
    const editor = this.editor;
    const doc = this.tip.ownerDocument;
    const { t } = editor.hooks.i18n();
    const snap = editor.drag?.snap ?? editor.keys.run?.snap ?? null;
    const held = editor.drag?.held;
    /** @type {HTMLElement[]} */
    const rows = [Object.assign(doc.createElement('div'), { textContent: this.describe(k) })];
    if (editor.drag?.fine)
      rows.push(
        Object.assign(doc.createElement('div'), {
          className: 'rl-tip-fine',
          textContent: t('edit.fineTip', { percent: Math.round(FINE_DRAG * 100) }),
        }),
      );
    if (snap)
      rows.push(
        Object.assign(doc.createElement('div'), {
          className: 'rl-tip-snap',
          textContent: `◆ ${t('snap.onto', { name: snap.name })}`,
        }),
      );
    if (held)
      rows.push(
        Object.assign(doc.createElement('div'), { className: 'rl-tip-held', textContent: t(`snap.held.${held}`) }),
      );
    // the neighbourhood's values flow in one paragraph (a narrow view keeps the tip short); an
    // exercise's conditions get a line each
    const values = Object.assign(doc.createElement('div'), { className: 'rl-tip-values' });
    /** @type {HTMLElement[]} */
    const goals = [];
    for (const line of editor.live.lines(k)) {
      const item = Object.assign(doc.createElement('span'), { className: 'rl-tip-value' });
      appendRich(item, line.label);
      if (line.holds === undefined) {
        item.append(` ${line.text}`);
        values.append(item, ' ');
      } else {
        item.classList.add(line.holds ? 'rl-holds' : 'rl-fails');
        item.append(`: ${line.text}${line.holds ? ' ✓' : ''}`);
        goals.push(item);
      }
    }
    if (values.childElementCount) rows.push(values);
    append(rows, goals);
    this.tip.replaceChildren(...rows);
  }

  /** The tip again with the values of a new computation (a drag's frame). */
  refresh() {
    if (!this.tip.hidden) this.showTip(Number(this.tip.dataset.handle));
  }

  hideTip() {
    this.tip.hidden = true;
  }

  /**
   * Draws the handles over the view after a frame (every one while editing; else the one under
   * the pointer, dragged or chosen), the selected one marked, and where a drag snapped.
   * @param {ArrayLike<number>} viewProj
   */
  place(viewProj) {
    const editor = this.editor;
    const doc = this.layer.ownerDocument;
    const { clientWidth: w, clientHeight: h } = editor.viewer.canvas;
    const all = editor.active ? editor.handles() : [];
    const dragged = editor.drag?.handle ?? -1;
    const chosen = editor.picked ? editor.selected : -1;
    const shown = all
      .map((handle, k) => ({ handle, k }))
      .filter(({ k }) => editor.editing || k === editor.hover || k === dragged || k === chosen);
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
      ring.classList.toggle('rl-selected', (editor.editing || editor.picked) && item.k === editor.selected);
      ring.dataset.handle = String(item.k);
    });
    const snap = editor.drag?.snap ?? editor.keys.run?.snap ?? null;
    this.snapMark.hidden = !snap;
    if (snap) {
      const s = toScreen(viewProj, snap.world, w, h);
      this.snapMark.style.transform = `translate(${s.x}px, ${s.y}px) rotate(45deg)`;
    }
    if (!this.tip.hidden && this.stale) {
      this.stale = false;
      this.fillTip(Number(this.tip.dataset.handle));
    }
    if (!this.tip.hidden) {
      const handle = all[Number(this.tip.dataset.handle)];
      if (handle) {
        const s = toScreen(viewProj, handle.world, w, h);
        // beside the handle (above it, or below where the top is near), never over it
        const tw = this.tip.offsetWidth,
          th = this.tip.offsetHeight;
        const x = Math.max(4, Math.min(s.x + 18, w - tw - 4));
        const above = s.y - th - 18;
        const y = above >= 4 ? above : Math.min(s.y + 22, h - th - 4);
        this.tip.style.transform = `translate(${x}px, ${y}px)`;
      } else this.tip.hidden = true; // its handle is gone (another scene, editing ended)
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
