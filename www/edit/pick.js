// Handles on top of each other on screen (the apex of a cone, where every ruling's end meets) are
// never a blob to guess in: a press there opens a short list of them by name beside the finger.
// The one chosen is selected and ringed, and the next press on the spot drags it (or its
// coordinates are typed, or the keyboard moves it). Escape or a press elsewhere closes the list.
import { PICK_LIST } from '../limits.js';

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
          this.close();
          editor.select(k, true);
          editor.marks.showTip(k);
          editor.viewer.canvas.focus({ preventScroll: true });
        });
        return b;
      }),
    );
    this.box.hidden = false;
    // beside the press, inside the view
    const view = editor.view.getBoundingClientRect();
    const w = this.box.offsetWidth,
      h = this.box.offsetHeight;
    const left = Math.max(4, Math.min(x + 16, view.width - w - 4));
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
