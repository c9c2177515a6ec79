// Editing in a stage: the editor of the scene's handles (edit/editor.js) with the buttons around
// it — ✎ (editing: every point ringed, the keyboard moves them), undo and redo in the toolbar,
// the edit bar (how a drag moves a point, snapping, Done), the chosen point's coordinates and
// values in the panel (edit/coords.js), the note "edited from …" with the way back to the
// built-in input, and "Edit as data" for a scene without handles. The editor's moves go to the
// stage as changes of the input (`ports.apply`: a dispatch); what is shown here is drawn from the
// state and what the core built (render) and the editor's history. Editing ends when the scene
// changes; entering it keeps the page where it is.
import { Editor } from '../edit/editor.js';
import { CoordsBox } from '../edit/coords.js';
import { appendRich } from '../ui/richtext.js';
import { labelButton } from './elements.js';
import { touchScreen } from './touch.js';
import { MAX_LINK_HANDLES } from '../limits.js';
import { decodeInput } from '../edit/input.js';

/** The sign of each way a drag moves a handle. */
const MODE_SIGNS = { view: '⊙', line: '⤡', vertical: '↕' };

/**
 * What editing asks of its stage.
 * @typedef {object} EditPorts
 * @property {import('./elements.js').StageElements} els
 * @property {import('../viewer.js').Viewer} viewer   where the handles are drawn over the figure
 * @property {() => import('../store.js').StageState} state
 * @property {() => import('../scene.js').Built | null} built   what the core built last
 * @property {() => import('../i18n/index.js').Translator} i18n
 * @property {(input: import('../scene.js').Input | null, ended: boolean, said: () => string) => void} apply
 *   the input moved (ended: the step is over; said: what it did, asked once computed)
 * @property {(text: string) => void} say   said to screen readers now
 * @property {((data: import('../scene.js').ImportedData) => void) | null} asData   "Edit as data", where the owner offers it
 */

/** Whether the reader may drag the handles now: the stage's choice, or the exercise's. */
export function mayEdit(/** @type {import('../store.js').StageState} */ state) {
  return state.exercise ? state.exercise.change.includes('handles') : state.editable;
}

/** The start edit of an exercise (its handles as it begins), once decoded per exercise. */
const starts = new WeakMap();
function startInput(/** @type {import('../task/format.js').Task | null} */ task) {
  if (!task) return null;
  if (!starts.has(task)) starts.set(task, task.input ? decodeInput(task.input) : null);
  return starts.get(task);
}

export class EditHost {
  /** @param {EditPorts} ports */
  constructor(ports) {
    this.ports = ports;
    const { els, viewer } = ports;
    this.editor = new Editor(els.view, viewer, {
      i18n: ports.i18n,
      current: () => ports.state().input,
      base: () => startInput(ports.state().exercise),
      // a move that ends says where it went, then (in an exercise) its conditions on the new figure
      apply: (input, ended, said) =>
        ports.apply(input, ended, () => [said, ended ? this.editor.live.summary() : ''].filter(Boolean).join('; ')),
      say: ports.say,
      changed: () => this.show(),
      built: ports.built,
      task: () => ports.state().exercise,
    });
    this.editor.enabled = mayEdit(ports.state());
    this.coords = new CoordsBox(this.editor, els.coords);
    /** @type {Array<{handle: string, why: string}>} an exercise's constraints that could not hold (said once) */
    this.lifted = [];
    viewer.overlays.push((m) => this.editor.place(m));
    els.buttons.edit.addEventListener('click', () => {
      this.editor.setEditing(!this.editor.editing);
      if (!this.editor.editing) return;
      // the keyboard goes to the view, the page stays where it is (the exercise in sight)
      els.canvas.focus({ preventScroll: true });
      if (this.covered()) viewer.fit();
    });
    els.buttons.undo.addEventListener('click', () => this.editor.undo());
    els.buttons.redo.addEventListener('click', () => this.editor.redo());
    els.done.addEventListener('click', () => this.editor.setEditing(false));
    els.snap.addEventListener('click', () => this.editor.setSnapping(!this.editor.snapOn));
    for (const [mode, button] of Object.entries(els.modes))
      button.addEventListener('click', () =>
        this.editor.setMode(/** @type {import('../edit/geometry.js').MoveMode} */ (mode)),
      );
    els.asData.addEventListener('click', () => {
      const data = ports.built()?.data;
      if (data) ports.asData?.({ segments: data.segments, ...(data.grid ?? {}) });
    });
  }

  /** Whether the reader may drag the handles (the stage's choice, or the exercise's). */
  get enabled() {
    return this.editor.enabled;
  }

  /**
   * Draws editing as the state stands and what the core built: whether the handles may move
   * (editing stops where they may not), the handles of the input built, "Edit as data", the buttons.
   * @param {import('../store.js').StageState} state
   * @param {import('../scene.js').Built | null} built
   */
  render(state, built) {
    const may = mayEdit(state);
    if (this.editor.enabled !== may) {
      this.editor.enabled = may;
      if (!may) this.editor.setEditing(false);
      this.ports.viewer.requestRender();
    }
    if (built) {
      this.editor.show(built.input);
      if (!(state.moving && state.input)) this.showAsData(state, built);
    }
    this.show();
  }

  /**
   * A scene (or its built-in input) shown anew: editing ends where the scene changed, the history
   * goes, the exercise's rules are taken (those that cannot hold are kept in `lifted`, for a note).
   * @param {import('../scene.js').Editable | null | undefined} editable
   * @param {boolean} sceneChanged
   */
  enter(editable, sceneChanged) {
    if (sceneChanged) this.editor.setEditing(false);
    this.lifted = this.editor.enter(editable, this.ports.state().exercise?.edit ?? null);
  }

  /** Whether a handle is hidden under the view's bars or outside the view (Fit frames them between). */
  covered() {
    const { els, viewer } = this.ports;
    const view = els.canvas.getBoundingClientRect();
    const bar = els.bar.getBoundingClientRect();
    const m = viewer.camera.viewProj(view.width / (view.height || 1));
    return this.editor.handles().some(({ world }) => {
      const cw = m[3] * world[0] + m[7] * world[1] + m[11] * world[2] + m[15];
      const x = (((m[0] * world[0] + m[4] * world[1] + m[8] * world[2] + m[12]) / cw + 1) / 2) * view.width;
      const y = ((1 - (m[1] * world[0] + m[5] * world[1] + m[9] * world[2] + m[13]) / cw) / 2) * view.height;
      return cw <= 0 || x < 0 || x > view.width || y < 0 || view.top + y > bar.top;
    });
  }

  /** The labels of the edit's buttons in the stage's language. */
  localize() {
    const { t } = this.ports.i18n();
    const { buttons, modes, modeLabel, modeGroup, done, asData, snap } = this.ports.els;
    labelButton(buttons.edit, '✎', t('edit.button'));
    buttons.edit.title = t('edit.buttonTitle');
    buttons.undo.textContent = '↶';
    buttons.undo.setAttribute('aria-label', t('edit.undo'));
    buttons.undo.title = t('edit.undoTitle');
    buttons.redo.textContent = '↷';
    buttons.redo.setAttribute('aria-label', t('edit.redo'));
    buttons.redo.title = t('edit.redoTitle');
    modeLabel.textContent = t('edit.moveLabel');
    modeGroup.setAttribute('aria-label', t('edit.moveLabel'));
    for (const [mode, button] of Object.entries(modes)) {
      labelButton(button, MODE_SIGNS[/** @type {keyof typeof MODE_SIGNS} */ (mode)], t(`edit.mode.${mode}`));
      button.title = t(`edit.mode.${mode}Title`);
    }
    labelButton(snap, '◈', t('edit.snap'));
    snap.title = t('edit.snapTitle');
    done.textContent = t('edit.done');
    asData.textContent = t('edit.asData');
    this.show();
  }

  /** The edit's buttons, its bar, its note and the view's hint, as the editor and the input stand. */
  show() {
    const state = this.ports.state();
    const { t } = this.ports.i18n();
    const els = this.ports.els;
    const editor = this.editor;
    const active = editor.active;
    els.buttons.edit.hidden = !active;
    els.buttons.edit.setAttribute('aria-pressed', String(editor.editing));
    els.buttons.undo.hidden = els.buttons.redo.hidden = !active || (!editor.canUndo && !editor.canRedo);
    els.buttons.undo.disabled = !editor.canUndo;
    els.buttons.redo.disabled = !editor.canRedo;
    els.editBar.hidden = !editor.editing;
    for (const [mode, button] of Object.entries(els.modes))
      button.setAttribute('aria-pressed', String(editor.mode === mode));
    els.modes.line.hidden = !editor.sets.some((set) => set.shape === 'pairs');
    els.snap.hidden = !editor.rules.exercise.snap;
    els.snap.setAttribute('aria-pressed', String(editor.snapOn));
    const doc = els.root.ownerDocument;
    // (in an exercise its own Start over takes the note's place)
    els.edited.hidden = !state.input || !!state.exercise;
    // (written again only when what it says changes: a drag calls this every frame)
    const note = `${editor.from}\n${state.inputNote}\n${t('edit.restore')}`;
    if (state.input && !state.exercise && els.edited.dataset.note !== note) {
      els.edited.dataset.note = note;
      const text = doc.createElement('p');
      appendRich(text, t('edit.from', { from: editor.from }));
      const back = Object.assign(doc.createElement('button'), { type: 'button', textContent: t('edit.restore') });
      back.addEventListener('click', () => {
        editor.restore();
        // (the note and its button are gone: the keyboard stays on the figure they were about)
        els.canvas.focus({ preventScroll: true });
      });
      const parts = [text, back];
      if (state.inputNote)
        parts.push(
          Object.assign(doc.createElement('p'), {
            className: 'rl-edited-note',
            textContent: t(state.inputNote, { max: MAX_LINK_HANDLES }),
          }),
        );
      els.edited.replaceChildren(...parts);
    }
    this.coords.show();
    els.root.classList.toggle('rl-has-handles', active);
    const touch = touchScreen();
    const hint = t(
      touch ? (active ? 'view.hintTouchEdit' : 'view.hintTouch') : active ? 'view.hintEdit' : 'view.hintMouse',
    );
    if (els.hint.textContent !== hint) els.hint.textContent = hint;
  }

  /** "Edit as data" where the scene offers it and the reader may edit. */
  showAsData(/** @type {import('../store.js').StageState} */ state, /** @type {import('../scene.js').Built} */ built) {
    this.ports.els.asData.hidden = !(state.scene?.editAsData && built.data && this.ports.asData && this.editor.enabled);
  }
}
