// Editing in a stage: the editor of the scene's handles (edit/editor.js) with the buttons around
// it — ✎ (keyboard editing), undo and redo in the toolbar, the edit bar (how a drag moves a
// handle, Done), the note "edited from …" with the way back to the built-in input, and "Edit as
// data" for a scene without handles. The editor's moves go to the stage as changes of the input
// (Stage.setInput); what is shown here follows the stage's state and the editor's history.
import { Editor } from '../edit/editor.js';
import { appendRich } from '../ui/richtext.js';
import { labelButton } from './elements.js';
import { touchScreen } from './touch.js';
import { MAX_LINK_HANDLES } from '../limits.js';

/** The sign of each way a drag moves a handle. */
const MODE_SIGNS = { view: '⊙', line: '⤡', vertical: '↕' };

export class EditHost {
  /** @param {import('../stage.js').Stage} stage */
  constructor(stage) {
    this.stage = stage;
    const els = stage.els;
    this.editor = new Editor(els.view, stage.viewer, {
      i18n: () => stage.i18n,
      current: () => stage.input,
      base: () => stage.exercise.startInput(),
      apply: (input, ended, said) => stage.setInput(input, ended, said),
      say: (text) => stage.announcer.say(text),
      changed: () => this.show(),
    });
    this.editor.enabled = !!stage.options.editable;
    stage.viewer.overlays.push((m) => this.editor.place(m));
    els.buttons.edit.addEventListener('click', () => {
      this.editor.setEditing(!this.editor.editing);
      if (this.editor.editing) els.canvas.focus();
    });
    els.buttons.undo.addEventListener('click', () => this.editor.undo());
    els.buttons.redo.addEventListener('click', () => this.editor.redo());
    els.done.addEventListener('click', () => this.editor.setEditing(false));
    for (const [mode, button] of Object.entries(els.modes))
      button.addEventListener('click', () =>
        this.editor.setMode(/** @type {import('../edit/geometry.js').MoveMode} */ (mode)),
      );
    els.asData.addEventListener('click', () => {
      const data = stage.session.built?.data;
      if (data) stage.options.onEditAsData?.({ segments: data.segments, ...(data.grid ?? {}) });
    });
  }

  /** Whether the reader may drag the handles (the stage's option, or the exercise's). */
  set enabled(on) {
    this.editor.enabled = on;
  }
  get enabled() {
    return this.editor.enabled;
  }

  /** The labels of the edit's buttons in the stage's language. */
  localize() {
    const { t } = this.stage.i18n;
    const { buttons, modes, modeLabel, modeGroup, done, asData } = this.stage.els;
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
    done.textContent = t('edit.done');
    asData.textContent = t('edit.asData');
    this.show();
  }

  /** The edit's buttons, its bar, its note and the view's hint, as the editor and the input stand. */
  show() {
    const stage = this.stage;
    const { t } = stage.i18n;
    const els = stage.els;
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
    const doc = els.root.ownerDocument;
    // (in an exercise its own Start over takes the note's place)
    els.edited.hidden = !stage.input || !!stage.task;
    if (stage.input && !stage.task) {
      const text = doc.createElement('p');
      appendRich(text, t('edit.from', { from: editor.from }));
      const back = Object.assign(doc.createElement('button'), { type: 'button', textContent: t('edit.restore') });
      back.addEventListener('click', () => editor.restore());
      const parts = [text, back];
      if (stage.inputNote)
        parts.push(
          Object.assign(doc.createElement('p'), {
            className: 'rl-edited-note',
            textContent: t(stage.inputNote, { max: MAX_LINK_HANDLES }),
          }),
        );
      els.edited.replaceChildren(...parts);
    }
    els.root.classList.toggle('rl-has-handles', active);
    const touch = touchScreen();
    els.hint.textContent = t(
      touch ? (active ? 'view.hintTouchEdit' : 'view.hintTouch') : active ? 'view.hintEdit' : 'view.hintMouse',
    );
  }

  /** "Edit as data" where the scene offers it and the reader may edit. */
  showAsData(/** @type {import('../scene.js').Built} */ built) {
    const stage = this.stage;
    stage.els.asData.hidden = !(
      stage.scene?.editAsData &&
      built.data &&
      stage.options.onEditAsData &&
      this.editor.enabled
    );
  }
}
