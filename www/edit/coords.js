// The chosen handle in the panel: its name, its coordinates in three fields a reader can type
// into (unless the exercise forbids it), and the values of its neighbourhood — a way to place a
// point exactly without a steady hand, and the live values in words for a keyboard or a screen
// reader. Typed coordinates keep the handle's constraint (the core takes them to the nearest
// point of its line or plane) and its box; one typed move is one step of undo.
import { snapPoint } from '../../pkg/ruledlab.js';
import { answerNumber } from '../task/check.js';
import { appendRich } from '../ui/richtext.js';
import { coordinates } from './marks.js';
import { cross, sub } from '../math.js';
import { coreConstraint, triple } from './snap.js';

let serial = 0;

export class CoordsBox {
  /**
   * @param {import('./editor.js').Editor} editor
   * @param {HTMLElement} box   its place in the panel
   */
  constructor(editor, box) {
    this.editor = editor;
    this.box = box;
    const doc = box.ownerDocument;
    const id = `rl-coords-${++serial}`;
    this.heading = Object.assign(doc.createElement('h3'), { id: `${id}-heading` });
    box.setAttribute('aria-labelledby', this.heading.id);
    this.form = Object.assign(doc.createElement('div'), { className: 'rl-coords-fields' });
    /** @type {HTMLInputElement[]} */
    this.fields = ['x', 'y', 'z'].map((c) => {
      const input = Object.assign(doc.createElement('input'), { type: 'text', id: `${id}-${c}`, inputMode: 'decimal' });
      input.setAttribute('autocomplete', 'off');
      input.addEventListener('keydown', (e) => {
        if (e.key === 'Enter') {
          e.preventDefault();
          this.apply();
        }
      });
      const label = Object.assign(doc.createElement('label'), { htmlFor: input.id, textContent: c });
      const cell = doc.createElement('span');
      cell.append(label, input);
      this.form.append(cell);
      return input;
    });
    this.set = Object.assign(doc.createElement('button'), { type: 'button', className: 'rl-coords-set' });
    this.set.addEventListener('click', () => this.apply());
    this.form.append(this.set);
    this.message = Object.assign(doc.createElement('p'), { className: 'rl-coords-message', hidden: true });
    this.message.setAttribute('role', 'status');
    this.values = Object.assign(doc.createElement('dl'), { className: 'rl-coords-values' });
    box.append(this.heading, this.form, this.message, this.values);
    /** @type {number} the handle the fields were filled for */
    this.shownFor = -1;
  }

  /** Shows the selected handle (while editing, or once one is chosen), or hides the box. */
  show() {
    const editor = this.editor;
    const { t, lang } = editor.hooks.i18n();
    const k = editor.selected;
    const handle = editor.active && (editor.editing || editor.picked) ? editor.handles()[k] : undefined;
    this.box.hidden = !handle;
    if (!handle) {
      this.shownFor = -1;
      return;
    }
    this.heading.textContent = t('edit.coords', { handle: editor.nameOf(handle) });
    const typed = editor.rules.exercise.typed;
    this.form.hidden = !typed;
    this.set.textContent = t('edit.coordsSet');
    // the fields follow the handle unless the reader is typing in one
    const active = this.box.ownerDocument.activeElement;
    const typing = this.fields.some((f) => f === active);
    if (!typing || this.shownFor !== k) {
      const f = new Intl.NumberFormat(lang, { maximumFractionDigits: 6, useGrouping: false });
      this.fields.forEach((field, c) => {
        // (a value that rounds to 0 shows as 0, not −0)
        const shown = Math.round(handle.point[c] * 1e6) / 1e6;
        field.value = f.format(shown === 0 ? 0 : shown).replace('-', '−');
      });
    }
    this.shownFor = k;
    const doc = this.box.ownerDocument;
    const lines = editor.live.lines(k);
    // (written again only when a value changed: a drag calls this every frame)
    const said = lines.map((line) => `${line.label} ${line.text} ${line.holds}`).join('\n');
    if (this.values.dataset.said === said) return;
    this.values.dataset.said = said;
    this.values.replaceChildren(
      ...lines.flatMap((line) => [
        appendRich(doc.createElement('dt'), line.label),
        Object.assign(doc.createElement('dd'), { textContent: `${line.text}${line.holds ? ' ✓' : ''}` }),
      ]),
    );
    this.values.hidden = !this.values.childElementCount;
    this.values.setAttribute('aria-label', t('edit.coordsValues'));
  }

  /** Puts the handle where the fields say (on its constraint, in the box), one step of undo. */
  apply() {
    const editor = this.editor;
    const { t, lang } = editor.hooks.i18n();
    const k = editor.selected;
    const handle = editor.handles()[k];
    if (!handle || !editor.rules.exercise.typed) return;
    const typed = this.fields.map((f) => answerNumber(f.value));
    const bad = typed.findIndex((x) => !Number.isFinite(x));
    if (bad >= 0) {
      this.say(t('edit.coordsBad', { axis: 'xyz'[bad] }));
      this.fields[bad].focus();
      return;
    }
    const point = this.onConstraint(handle, typed);
    if (!point) {
      this.say(t('edit.coordsHeld'));
      return;
    }
    const moved = editor.moveTo(k, point, `${editor.nameOf(handle)}: ${coordinates(point, lang)}`);
    this.say(moved ? '' : t('edit.coordsSame'));
  }

  /**
   * The typed point taken to the handle's constraint by the core (its shadow on a line or a
   * plane), inside the box; null where the handle is fixed or the constraint cannot hold.
   * @param {import('./editor.js').Handle} handle @param {number[]} p
   */
  onConstraint(handle, p) {
    const editor = this.editor;
    const held = editor.rules.held(handle);
    const box = editor.box ?? { min: [-1e9, -1e9, -1e9], max: [1e9, 1e9, 1e9] };
    if (!held) return p;
    if (held.kind === 'fixed') return null;
    // a ray through the typed point orthogonal to the line (along the plane's normal) meets it
    // at the typed point's shadow
    const along = held.kind === 'line' ? held.direction : held.normal;
    const other = Math.abs(along[0]) < 0.9 * Math.hypot(...along) ? [1, 0, 0] : [0, 1, 0];
    const direction = held.kind === 'line' ? cross(along, other) : along;
    const placed = snapPoint({
      ray: { origin: triple(sub(p, direction)), direction: triple(direction) },
      start: triple(handle.point),
      constraint: coreConstraint(held),
      targets: [],
      bounds: { min: triple(box.min), max: triple(box.max) },
    });
    return placed.point ? Array.from(placed.point) : null;
  }

  /** A word under the fields (empty: none). */
  say(/** @type {string} */ text) {
    this.message.textContent = text;
    this.message.hidden = !text;
  }
}
