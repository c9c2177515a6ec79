// Editing from the keyboard (while the view has focus and editing is on): Tab / Shift+Tab and
// ] / [ step through the handles (Tab past the last one, Shift+Tab before the first, go on to the
// page: the edit bar and the typed coordinates after the view), the arrow keys move the selected
// one across the view, PageUp / PageDown away from and towards the viewer, Shift a tenth of the
// step (and no snapping); M changes the mode (facing you, along its line, along z); the mode and
// the constraints hold as for a drag, and a step that ends near a target is snapped onto it by
// the core. Enter ends a run of moves (one step of undo), Escape cancels it, or hides the tip an
// exercise keeps with its conditions, and then stops editing; S turns snapping on and off.
import { inputOf, copyInput, sameInput } from './input.js';
import { toScreen, transformPoint } from './geometry.js';
import { constraintOf } from './snap.js';
import { normalize, sub, cross, add, scale } from '../math.js';
import { KEY_STEP, SNAP_REACH } from '../limits.js';

/** A run of key moves on one handle ends after this pause (ms): it is one step of undo. */
const KEY_RUN = 1000;

export class KeyInput {
  /** @param {import('./editor.js').Editor} editor */
  constructor(editor) {
    this.editor = editor;
    /** @type {{handle: number, before: import('../scene.js').Input | null, working: import('../scene.js').Input, initial: import('../scene.js').Input, timer: number, snap: import('./snap.js').Placed['snap']} | null} a run of key moves */
    this.run = null;
    // while editing, the view's keys move handles (before the camera, which would turn on arrows)
    editor.view.addEventListener(
      'keydown',
      (e) => {
        if (e.target === editor.viewer.canvas && this.key(e)) e.stopImmediatePropagation();
      },
      { capture: true },
    );
  }

  /** A key pressed on the view while editing; true when it was the editor's. */
  key(/** @type {KeyboardEvent} */ e) {
    const editor = this.editor;
    if (e.ctrlKey || e.metaKey || e.altKey) return false;
    if ((e.key === 's' || e.key === 'S') && editor.active && editor.rules.exercise.snap) {
      editor.setSnapping(!editor.snapOn);
      e.preventDefault();
      return true;
    }
    // a tip an exercise keeps with its conditions may always be dismissed (after a move, before
    // editing stops; a mouse user's too)
    if (e.key === 'Escape' && !this.run && !editor.marks.tip.hidden) {
      editor.marks.hideTip();
      e.preventDefault();
      return true;
    }
    if (!editor.editing) return false;
    const count = editor.handles().length;
    if (!count) return false;
    const { camera } = editor.viewer;
    const forward = normalize(sub(camera.target, camera.eye));
    const right = normalize(cross(forward, [0, 0, 1]));
    const up = cross(right, forward);
    const step = editor.size * KEY_STEP * (e.shiftKey ? 0.1 : 1);
    /** @type {Record<string, number[]>} */
    const moves = {
      ArrowLeft: scale(right, -step),
      ArrowRight: scale(right, step),
      ArrowUp: scale(up, step),
      ArrowDown: scale(up, -step),
      PageUp: scale(forward, step),
      PageDown: scale(forward, -step),
    };
    if (e.key === 'Tab' || e.key === ']' || e.key === '[') {
      const back = e.key === '[' || (e.key === 'Tab' && e.shiftKey);
      // (Tab at either end leaves the view, as Tab does: no trap)
      if (e.key === 'Tab' && editor.selected === (back ? 0 : count - 1)) return false;
      editor.select((editor.selected + (back ? count - 1 : 1)) % count);
    } else if (e.key === 'm' || e.key === 'M') {
      editor.nextMode();
    } else if (moves[e.key]) {
      this.nudge(moves[e.key], !e.shiftKey);
    } else if (e.key === 'Escape') {
      if (this.run) this.cancel();
      else editor.setEditing(false);
    } else if (e.key === 'Enter') {
      this.end();
    } else return false;
    e.preventDefault();
    return true;
  }

  /**
   * @internal Moves the selected handle by a world vector, as the drag's mode and constraints
   * allow, snapped where `snap` (a run of key moves is one undo step).
   */
  nudge(/** @type {number[]} */ by, snap = true) {
    const editor = this.editor;
    const k = editor.selected;
    if (!this.run) {
      const before = editor.hooks.current();
      this.run = {
        handle: k,
        before,
        working: inputOf(editor.sets),
        initial: inputOf(editor.sets),
        timer: 0,
        snap: null,
      };
      editor.snapper.begin(k);
      editor.live.begin();
    }
    const run = this.run;
    clearTimeout(run.timer);
    run.timer = window.setTimeout(() => this.end(), KEY_RUN);
    const handle = editor.handles()[k];
    const set = editor.sets[handle.set];
    const world = add(handle.world, by);
    const inverse = editor.inverseOf(handle.set);
    const wanted = inverse ? transformPoint(inverse, world) : world;
    const { camera, canvas } = editor.viewer;
    const r = canvas.getBoundingClientRect();
    const w = r.width || 1,
      h = r.height || 1;
    const s = toScreen(camera.viewProj(w / h), transformPoint(set.transform, wanted), w, h);
    const forward = normalize(sub(camera.target, camera.eye));
    const constraint = constraintOf(editor, handle, editor.mode, forward);
    // facing the viewer the step is the key's own (depth too); on a line or plane, its shadow there
    const start = constraint.kind === 'view' ? wanted : handle.point;
    const placed = editor.snapper.place(handle, start, constraint, s.x, s.y, snap && s.visible ? SNAP_REACH : 0);
    // a step leaves what the point is on: a snap back to where the step began is no step
    if (
      placed.snap &&
      placed.point?.every((x, c) => Math.abs(x - handle.point[c]) <= 1e-12 * Math.max(1, Math.abs(x)))
    ) {
      placed.point = placed.free;
      placed.snap = null;
    }
    const { t } = editor.hooks.i18n();
    if (placed.held) editor.hooks.say(t(`snap.held.${placed.held}`));
    if (!placed.point) return;
    run.snap = placed.snap;
    editor.put(run.working, k, placed.point);
    editor.marks.showTip(k);
    if (placed.snap) editor.marks.sayNow(t('snap.onto', { name: placed.snap.name }));
    else editor.marks.sayLater(k);
    editor.hooks.apply(copyInput(run.working), false);
    editor.hooks.changed();
  }

  /** Ends a run of key moves: one step of undo. */
  end() {
    const editor = this.editor;
    const run = this.run;
    if (!run) return;
    clearTimeout(run.timer);
    editor.marks.quiet();
    // in an exercise the tip stays with its conditions (as after a drag)
    if (!editor.live.outcomes().length) editor.marks.hideTip();
    const { t } = editor.hooks.i18n();
    const said = [editor.describe(run.handle), run.snap && t('snap.onto', { name: run.snap.name })]
      .filter(Boolean)
      .join('; ');
    this.run = null;
    if (!sameInput(run.working, run.initial)) {
      editor.record(run.before);
      editor.hooks.apply(run.working, true, said);
    }
  }

  /** Escape during a run of key moves: the handle goes back. */
  cancel() {
    const editor = this.editor;
    const run = this.run;
    if (!run) return;
    clearTimeout(run.timer);
    this.run = null;
    editor.marks.hideTip();
    editor.hooks.apply(run.before, true, editor.hooks.i18n().t('edit.cancelled'));
    editor.hooks.changed();
  }
}
