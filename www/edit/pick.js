// Handles on top of each other on screen (the apex of a cone, where every ruling's end meets) are
// never a blob to guess in: a press there opens a short list of them by name beside the finger.
// The one chosen is selected and ringed, and the next press on the spot drags it (or its
// coordinates are typed, or the keyboard moves it). Escape or a press elsewhere closes the list.
import { PICK_LIST } from '../limits.js';

/** A click this soon after the list opened (ms) is the end of the press that opened it. */
const PICK_SETTLE = 350;

export class PickList {
  /** @param {import('./editor.js').Editor} editor */
  constructor(editor) {
    this.editor = editor;
    const doc = editor.view.ownerDocument;
    this.box = Object.assign(doc.createElement('div'), { className: 'rl-pick', hidden: true });
    this.box.setAttribute('role', 'group');
    this.heading = Object.assign(doc.createElement('p'), { className: 'rl-pick-heading' });
    this.list = Object.assign(doc.createElement('div'), { className: 'rl-pick-list' });
    this.box.append(this.heading, this.list);
    this.box.addEventListener('keydown', (e) => {
      if (e.key === 'Escape') {
        e.stopPropagation();
        this.close();
        editor.viewer.canvas.focus({ preventScroll: true });
      }
    });
    editor.view.append(this.box);
    this.openedAt = 0;
  }

  /** Whether the list is open. */
  get shown() {
    return !this.box.hidden;
  }

  /**
   * Opens the list of handles `ks` (nearest first; at most PICK_LIST) beside (x, y), CSS px of
   * the view.
   * @param {number[]} ks @param {number} x @param {number} y
   */
  open(ks, x, y) {
    const editor = this.editor;
    const { t } = editor.hooks.i18n();
    const doc = this.box.ownerDocument;
    const handles = editor.handles();
    const shown = ks.slice(0, PICK_LIST);
    this.heading.textContent = t('edit.pick', { count: ks.length });
    this.box.setAttribute('aria-label', this.heading.textContent);
    this.list.replaceChildren(
      ...shown.map((k) => {
        const b = Object.assign(doc.createElement('button'), {
          type: 'button',
          textContent: editor.nameOf(handles[k]),
        });
        b.dataset.handle = String(k);
        b.addEventListener('click', () => {
          // (the press that opened the list ends in a click a browser may give to a button near
          // the finger: not a choice)
          if (performance.now() - this.openedAt < PICK_SETTLE) return;
          this.close();
          editor.select(k, true);
          editor.marks.showTip(k);
          editor.viewer.canvas.focus({ preventScroll: true });
        });
        return b;
      }),
    );
    this.box.hidden = false;
    this.openedAt = performance.now();
    // beside the press (clear of the finger), inside the view
    const view = editor.view.getBoundingClientRect();
    const w = this.box.offsetWidth,
      h = this.box.offsetHeight;
    const left = x + 32 + w < view.width - 4 ? x + 32 : Math.max(4, x - 32 - w);
    const top = Math.max(4, Math.min(y - h / 2, view.height - h - 4));
    this.box.style.transform = `translate(${left}px, ${top}px)`;
    /** @type {HTMLElement | null} */ (this.list.firstElementChild)?.focus({ preventScroll: true });
    editor.hooks.say(this.heading.textContent);
  }

  /** Closes the list. */
  close() {
    this.box.hidden = true;
  }
}
