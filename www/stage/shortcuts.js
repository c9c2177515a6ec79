// The keys of a stage and the list of them: ? opens the list of gestures (first, on a touch
// screen) and keys, R resets, Space plays or pauses, "." steps, D says what the figure shows, E
// starts keyboard editing, Ctrl+Z and Ctrl+Shift+Z / Ctrl+Y undo and redo an edit (the view's
// own keys are the camera's: camera.js; S and the keys that move a point are the editor's:
// edit/keys.js). Every key asks the stage for the change a button would make (`ports`).
import { touchScreen } from './touch.js';

/** The keys of the view and what each does (i18n keys). @type {Array<[string, string]>} */
const KEYS = [
  ['←  →  ↑  ↓', 'keys.orbit'],
  ['J  L  I  K', 'keys.orbitLetters'],
  ['Shift + ←  →  ↑  ↓', 'keys.pan'],
  ['+  −', 'keys.zoom'],
  ['F  0  Home', 'keys.fit'],
  ['D', 'keys.describe'],
  ['[  ]', 'keys.kleinMark'],
  ['R', 'keys.reset'],
  ['Space', 'keys.play'],
  ['.', 'keys.step'],
  ['Tab', 'keys.tab'],
  ['?', 'keys.help'],
  ['Esc', 'keys.close'],
];
/** The keys of editing. @type {Array<[string, string]>} */
const EDIT_KEYS = [
  ['E', 'keys.edit'],
  ['Tab  Shift+Tab  [  ]', 'keys.editStep'],
  ['←  →  ↑  ↓', 'keys.editMove'],
  ['PageUp  PageDown', 'keys.editDepth'],
  ['M', 'keys.editMode'],
  ['Shift', 'keys.editFine'],
  ['S', 'keys.snap'],
  ['Enter', 'keys.editEnd'],
  ['Esc', 'keys.editCancel'],
  ['Ctrl+Z', 'keys.undo'],
  ['Ctrl+Shift+Z  Ctrl+Y', 'keys.redo'],
];
/** The gestures on a touch screen. @type {Array<[string, string]>} */
const GESTURES = [
  ['touch.one', 'touch.oneWhat'],
  ['touch.two', 'touch.twoWhat'],
  ['touch.pinch', 'touch.pinchWhat'],
  ['touch.fit', 'touch.fitWhat'],
];
/** … and those of editing. @type {Array<[string, string]>} */
const EDIT_GESTURES = [
  ['touch.handle', 'touch.handleWhat'],
  ['touch.hold', 'touch.holdWhat'],
  ['touch.tap', 'touch.tapWhat'],
  ['touch.blob', 'touch.blobWhat'],
];

/**
 * What the keys ask of the stage.
 * @typedef {object} ShortcutPorts
 * @property {HTMLElement} host      the element the stage fills
 * @property {boolean} page          the page's stage: it takes the keys pressed with nothing focused too
 * @property {() => import('../i18n/index.js').Translator} i18n
 * @property {{active: () => boolean, editing: () => boolean, toggle: () => void, undo: () => void, redo: () => void}} edit
 *   the edit of the scene's handles (the edit host's)
 * @property {() => void} reset
 * @property {() => void} play       Space: play or pause the parameter that may move
 * @property {() => void} step       ".": a single step of it
 * @property {() => void} describe   D: the figure said again
 */

export class Shortcuts {
  /**
   * @param {import('./elements.js').StageElements} els
   * @param {ShortcutPorts} ports
   */
  constructor(els, ports) {
    this.els = els;
    this.ports = ports;
    this.dialog = els.shortcuts;
    els.root.addEventListener('keydown', (e) => this.key(e));
    // the page's stage also takes the keys pressed with nothing focused (undo after a drag elsewhere)
    this.onDocumentKey = (/** @type {KeyboardEvent} */ e) => {
      if (e.target === ports.host.ownerDocument.body) this.key(e);
    };
    if (ports.page) ports.host.ownerDocument.addEventListener('keydown', this.onDocumentKey);
  }

  /** Stops listening to the document's keys. */
  dispose() {
    this.ports.host.ownerDocument.removeEventListener('keydown', this.onDocumentKey);
  }

  /** Handles a key pressed in the stage (or, on the page, with nothing focused). */
  key(/** @type {KeyboardEvent} */ e) {
    const { edit } = this.ports;
    const target = /** @type {HTMLElement} */ (e.target);
    if (target.matches?.('input[type=text], textarea, select')) return;
    // undo and redo of the edit, wherever the keyboard is in the stage
    if ((e.ctrlKey || e.metaKey) && !e.altKey && edit.active()) {
      const k = e.key.toLowerCase();
      if (k === 'z' || k === 'y') {
        e.preventDefault();
        if (k === 'y' || e.shiftKey) edit.redo();
        else edit.undo();
      }
      return;
    }
    if (e.ctrlKey || e.metaKey || e.altKey) return;
    const onView = target === this.els.canvas;
    if (onView && (e.key === 'e' || e.key === 'E') && edit.active()) {
      e.preventDefault();
      edit.toggle();
    } else if (e.key === '?') {
      e.preventDefault();
      this.open();
    } else if (onView && (e.key === 'r' || e.key === 'R')) {
      e.preventDefault();
      this.ports.reset();
    } else if (onView && e.key === ' ') {
      e.preventDefault();
      this.ports.play();
    } else if (onView && (e.key === 'd' || e.key === 'D')) {
      e.preventDefault();
      this.ports.describe();
    } else if (onView && e.key === '.') {
      e.preventDefault();
      this.ports.step();
    }
  }

  /** Opens the list. */
  open() {
    if (this.dialog.open) return;
    this.build();
    this.dialog.showModal?.();
    this.dialog.scrollTop = 0;
  }

  /** The list in the stage's language, if it is open (a closed list costs the start nothing). */
  localize() {
    if (this.dialog.open) this.build();
  }

  /** Builds the list of gestures (first, on a touch screen) and keys. */
  build() {
    const { t } = this.ports.i18n();
    const doc = this.dialog.ownerDocument;
    const editing = this.ports.edit.active();
    /** @param {Array<[string, string]>} rows @param {boolean} [keyCaps] */
    const table = (rows, keyCaps = true) => {
      const tab = doc.createElement('table');
      for (const [k, what] of rows) {
        const row = tab.insertRow();
        // keys by the names on the reader's keyboard (German: Strg, Umschalt, Leertaste, Bild↑)
        const name = keyCaps
          ? k.replace(/\b(Shift|Ctrl|Space|PageUp|PageDown|Enter|Home)\b/g, (m) => t(`key.${m}`))
          : t(k);
        row.insertCell().append(Object.assign(doc.createElement(keyCaps ? 'kbd' : 'strong'), { textContent: name }));
        row.insertCell().textContent = t(what);
      }
      return tab;
    };
    const touch = table([...GESTURES, ...(editing ? EDIT_GESTURES : [])], false);
    touch.className = 'rl-gestures';
    // Close first: the dialog opens at its top with the keyboard on Close (a phone shows the
    // gestures, not the end of the list)
    const close = Object.assign(doc.createElement('button'), {
      type: 'button',
      className: 'rl-shortcuts-close',
      textContent: t('keys.closeButton'),
    });
    close.addEventListener('click', () => this.dialog.close());
    const heading = (/** @type {string} */ key) => Object.assign(doc.createElement('h2'), { textContent: t(key) });
    const intro = Object.assign(doc.createElement('p'), { textContent: t('keys.intro') });
    const gestures = [heading('touch.title'), touch];
    const keyboard = [heading('keys.title'), intro, table(KEYS)];
    if (editing) keyboard.push(heading('keys.editTitle'), table(EDIT_KEYS));
    this.dialog.setAttribute('aria-label', t(touchScreen() ? 'touch.dialog' : 'keys.title'));
    // on a touch screen the gestures come first; the keys stay for a keyboard attached to it
    this.dialog.replaceChildren(close, ...(touchScreen() ? [...gestures, ...keyboard] : [...keyboard, ...gestures]));
  }
}
