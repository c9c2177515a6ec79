// Editing a scene's input by its handles (scene.js: Editable, HandleSet): the state of an edit —
// the handles, the move mode, snapping, what holds a handle, the selected handle, undo and redo —
// and what every way of moving a handle shares: where a move puts it (edit/snap.js: the core
// decides, exactly), one computation per animation frame, one step of undo per drag or run of key
// moves, restoring the input bit for bit. The ways of moving are in their own files: the pointer
// and the finger (edit/pointer.js: drags, fine drags after a long press, the list of overlapping
// handles, edit/pick.js), the keyboard (edit/keys.js) and typed coordinates (edit/coords.js);
// what is shown over the view and said in words is edit/marks.js and edit/values.js.
import { copyInput, inputOf, sameInput } from './input.js';
import { HandleMarks } from './marks.js';
import { clampTo, editBox, invertSimilarity, transformPoint } from './geometry.js';
import { PointerInput } from './pointer.js';
import { KeyInput } from './keys.js';
import { PickList } from './pick.js';
import { Rules } from './rules.js';
import { Snapper } from './snap.js';
import { LiveValues } from './values.js';
import { EDIT_BOX } from '../limits.js';
import { greatest } from '../reduce.js';

/**
 * One handle: its set, its index in the set, and where it is.
 * @typedef {object} Handle
 * @property {number} set      index into the sets
 * @property {number} index    handle index in its set
 * @property {string} key      the set's key
 * @property {number[]} point  in the scene's input coordinates
 * @property {number[]} world  where it is drawn
 */

/**
 * What the editor needs of its stage.
 * @typedef {object} EditorHooks
 * @property {() => import('../i18n/index.js').Translator} i18n
 * @property {() => import('../scene.js').Input | null} current   the edited input, null for the built-in one
 * @property {() => import('../scene.js').Input | null} [base]   what "back" restores (an exercise's start
 *   edit; default the built-in input)
 * @property {(input: import('../scene.js').Input | null, ended: boolean, said?: string) => void} apply
 *   computes on it; `said`: what the step did, in words, to say before the readout
 * @property {(text: string) => void} say   for screen readers (polite)
 * @property {() => void} changed   the editor's own state changed (mode, history, selection): update buttons
 * @property {() => import('../scene.js').Built | null} [built]   what is shown now (its live values)
 * @property {() => import('../task/format.js').Task | null} [task]   the exercise, whose conditions are shown live
 */

/**
 * The drag in progress.
 * @typedef {object} Drag
 * @property {number} pointer
 * @property {number} handle
 * @property {import('../scene.js').Input | null} before
 * @property {import('../scene.js').Input} working
 * @property {import('../scene.js').Input} initial
 * @property {number[]} start     the handle when the drag (or its mode) began, input coordinates
 * @property {{x: number, y: number}} grab     the pointer then (client px)
 * @property {{x: number, y: number}} offset   the handle's place on screen less the pointer's then (CSS px)
 * @property {import('./geometry.js').MoveMode} mode
 * @property {boolean} moved
 * @property {boolean} fine       a long press made it fine: the handle follows at FINE_DRAG of the pointer's speed
 * @property {number} timer
 * @property {boolean} touch
 * @property {import('./snap.js').Placed['snap']} snap   what the handle is snapped onto
 * @property {string | null} held   why the handle does not follow (the core's reason)
 */

export class Editor {
  /**
   * @param {HTMLElement} view    the view's box (handles are drawn in it, pointers caught on it)
   * @param {import('../viewer.js').Viewer} viewer
   * @param {EditorHooks} hooks
   */
  constructor(view, viewer, hooks) {
    this.view = view;
    this.viewer = viewer;
    this.hooks = hooks;
    /** whether handles may be grabbed at all (<ruled-view editable>, #embed&edit, the page) */
    this.enabled = false;
    /** keyboard editing: every handle shown, arrows move the selected one */
    this.editing = false;
    /** @type {import('./geometry.js').MoveMode} the mode of the buttons (modifier keys override it) */
    this.mode = 'view';
    /** whether the reader wants drags to snap (the toggle, S); an exercise may forbid it */
    this.snapOn = true;
    /** @type {import('../scene.js').HandleSet[]} */
    this.sets = [];
    /** @type {string} what the built-in input is ("the hyperboloid of Example 1, 36 rulings") */
    this.from = '';
    /** @type {{min: number[], max: number[]} | null} where handles may go, in input coordinates */
    this.box = null;
    /** the largest extent of the built-in handles: a key moves a handle by a share of it */
    this.size = 1;
    /** @type {Array<import('../scene.js').Input | null>} */
    this.past = [];
    /** @type {Array<import('../scene.js').Input | null>} */
    this.future = [];
    /** @type {number} the selected handle (keyboard, a tap, the list), an index into handles() */
    this.selected = 0;
    /** whether the selection was chosen (a tap, the list, the keyboard): a press on a blob takes it */
    this.picked = false;
    /** @type {number} the handle under the pointer, or -1 */
    this.hover = -1;
    /** @type {Drag | null} */
    this.drag = null;
    /** @type {import('../scene.js').Input | null} the input waiting for the next animation frame */
    this.pending = null;
    this.frame = 0;
    /** @type {Map<number, Float64Array>} the inverse transforms of the sets drawn moved */
    this.inverses = new Map();
    /** what holds the handles (an exercise's constraints) */
    this.rules = new Rules();
    this.snapper = new Snapper(this);
    /** the values beside a moving handle */
    this.live = new LiveValues(this);
    /** the handles drawn over the view, the tip beside one, and their words */
    this.marks = new HandleMarks(this);
    this.pick = new PickList(this);
    this.pointer = new PointerInput(this);
    this.keys = new KeyInput(this);
  }

  /** Every handle, in order (set by set). */
  handles() {
    /** @type {Handle[]} */
    const out = [];
    const input = this.drag?.working ?? this.keys.run?.working ?? null;
    this.sets.forEach((set, s) => {
      const points = input?.[set.key] ?? set.points;
      for (let i = 0; 3 * i + 2 < points.length; i++) {
        const point = [points[3 * i], points[3 * i + 1], points[3 * i + 2]];
        out.push({ set: s, index: i, key: set.key, point, world: transformPoint(set.transform, point) });
      }
    });
    return out;
  }

  /** The inverse of set `s`'s transform (null where it is drawn as it is). */
  inverseOf(/** @type {number} */ s) {
    const m = this.sets[s]?.transform;
    if (!m) return null;
    let inverse = this.inverses.get(s);
    if (!inverse) {
      inverse = invertSimilarity(m);
      this.inverses.set(s, inverse);
    }
    return inverse;
  }

  /** Whether a drag snaps now (the reader's toggle, unless the exercise forbids snapping). */
  get snapping() {
    return this.snapOn && this.rules.exercise.snap;
  }

  /**
   * The handles of a new build: their positions come from the core (unless a drag or a run of
   * key moves is in progress, whose own positions stay under the pointer).
   * @param {import('../scene.js').Editable | null | undefined} editable
   */
  show(editable) {
    this.sets = editable?.sets ?? [];
    this.inverses.clear();
    this.from = editable?.from ?? this.from;
    if (!this.sets.length) this.setEditing(false);
    this.selected = Math.min(this.selected, Math.max(0, this.handles().length - 1));
    this.marks.refresh();
    this.viewer.requestRender();
  }

  /**
   * A new scene (or new settings of the built-in input): no history, handles kept in its box, the
   * exercise's rules taken; returns the exercise's constraints that cannot hold (lifted).
   * @param {import('../scene.js').Editable | null | undefined} editable
   * @param {import('./rules.js').EditRules | null} [rules]
   */
  enter(editable, rules = null) {
    this.cancel();
    this.pick.close();
    // (a tip kept with an exercise's conditions belongs to the figure before)
    this.marks.hideTip();
    this.past = [];
    this.future = [];
    this.selected = 0;
    this.picked = false;
    const box = editable?.sets.length ? boxOf(editable.sets) : null;
    this.box = box ? editBox(box, EDIT_BOX) : null;
    this.size = box
      ? greatest(
          box.max.map((b, k) => b - box.min[k]),
          1e-6,
        )
      : 1;
    this.show(editable);
    const lifted = this.rules.take(this.sets, rules);
    this.hooks.changed();
    return lifted;
  }

  /** Whether the scene has handles and the reader may grab them. */
  get active() {
    return this.enabled && this.sets.length > 0;
  }

  /** Keyboard editing on or off (every handle shown, arrows move the selected one). */
  setEditing(/** @type {boolean} */ on) {
    on = on && this.active;
    if (on === this.editing) return;
    this.keys.end();
    this.pick.close();
    if (!on) this.marks.hideTip();
    this.editing = on;
    this.view.classList.toggle('rl-editing', on);
    const { t } = this.hooks.i18n();
    if (on) {
      const count = this.handles().length;
      this.selected = Math.min(this.selected, count - 1);
      this.hooks.say(`${t('edit.entered', { count })} ${this.describe(this.selected)}`);
    } else this.hooks.say(t('edit.left'));
    this.hooks.changed();
    this.viewer.requestRender();
  }

  /** The move mode of the buttons. */
  setMode(/** @type {import('./geometry.js').MoveMode} */ mode) {
    this.mode = mode;
    this.hooks.changed();
  }

  /** The next move mode the handles have (M): facing you, along its line (lines only), along z; said. */
  nextMode() {
    /** @type {import('./geometry.js').MoveMode[]} */
    const modes = this.sets.some((set) => set.shape === 'pairs') ? ['view', 'line', 'vertical'] : ['view', 'vertical'];
    this.setMode(modes[(modes.indexOf(this.mode) + 1) % modes.length]);
    const { t } = this.hooks.i18n();
    this.hooks.say(t('edit.modeSaid', { mode: t(`edit.mode.${this.mode}`) }));
  }

  /** Snapping on or off (the toggle, S), said in words. */
  setSnapping(/** @type {boolean} */ on) {
    this.snapOn = on;
    this.hooks.say(this.hooks.i18n().t(on ? 'snap.on' : 'snap.off'));
    this.hooks.changed();
  }

  /** Whether an undo step exists. */
  get canUndo() {
    return this.past.length > 0 || !!this.drag?.moved || !!this.keys.run;
  }
  get canRedo() {
    return this.future.length > 0;
  }

  /** Takes back the last step (a drag, a run of key moves, typed coordinates, a reset of the input). */
  undo() {
    this.cancel();
    if (!this.past.length) return;
    this.future.push(this.hooks.current());
    this.hooks.apply(
      /** @type {import('../scene.js').Input | null} */ (this.past.pop()),
      true,
      this.hooks.i18n().t('edit.undone'),
    );
    this.hooks.changed();
  }

  redo() {
    this.cancel();
    if (!this.future.length) return;
    this.past.push(this.hooks.current());
    this.hooks.apply(
      /** @type {import('../scene.js').Input | null} */ (this.future.pop()),
      true,
      this.hooks.i18n().t('edit.redone'),
    );
    this.hooks.changed();
  }

  /** Back to the built-in input (or an exercise's start), as one step of undo. */
  restore() {
    this.cancel();
    const now = this.hooks.current();
    const base = this.hooks.base?.() ?? null;
    if (sameInput(now, base)) return;
    this.record(now);
    this.hooks.apply(base && copyInput(base), true, this.hooks.i18n().t('edit.restored'));
  }

  /** Replaces the input (<ruled-view>'s `data`), as one step of undo. */
  replace(/** @type {import('../scene.js').Input} */ input) {
    this.cancel();
    this.record(this.hooks.current());
    this.hooks.apply(copyInput(input), true);
  }

  /**
   * Puts handle `k` at `point` (input coordinates: the core's place, or typed) as one step of
   * undo; `said`: the step in words. Returns whether it moved.
   */
  moveTo(/** @type {number} */ k, /** @type {number[]} */ point, /** @type {string} */ said = '') {
    this.cancel();
    const before = this.hooks.current();
    const working = inputOf(this.sets);
    const initial = inputOf(this.sets);
    if (!this.put(working, k, point) || sameInput(working, initial)) return false;
    this.record(before);
    this.hooks.apply(working, true, said);
    return true;
  }

  /** @internal A step of undo: the input before it. */
  record(/** @type {import('../scene.js').Input | null} */ before) {
    this.past.push(before);
    this.future = [];
    this.hooks.changed();
  }

  /** Stops whatever is in progress, keeping what it did. */
  cancel() {
    this.pointer.cancel(false);
    this.keys.end();
  }

  /**
   * @internal Puts handle `k` of `input` at `p` (input coordinates, kept in the box); a tool's
   * tip carries its axis end along (the tool moves), the axis end alone turns it. Returns
   * whether it was put.
   */
  put(/** @type {import('../scene.js').Input} */ input, /** @type {number} */ k, /** @type {number[]} */ p) {
    const handle = this.handles()[k];
    if (!handle) return false;
    if (this.box) p = clampTo(p, this.box);
    if (!p.every(Number.isFinite)) return false;
    const points = input[handle.key];
    const at = 3 * handle.index;
    if (this.sets[handle.set].carry && handle.index % 2 === 0) {
      const box = this.box;
      const moved = [0, 1, 2].map((c) => points[at + 3 + c] + p[c] - points[at + c]);
      if (box && moved.some((x, c) => x < box.min[c] || x > box.max[c])) return false;
      points.set(moved, at + 3);
    }
    points.set(p, at);
    return true;
  }

  /** @internal Computes on `input` at the next animation frame (one computation per frame while dragging). */
  schedule(/** @type {import('../scene.js').Input} */ input) {
    const first = !this.pending;
    this.pending = input;
    if (!first) return;
    this.frame = requestAnimationFrame(() => {
      const next = this.pending;
      this.pending = null;
      if (next) this.hooks.apply(copyInput(next), false);
      // drawn in this frame, the frame the move asked for included
      this.viewer.renderNow();
    });
  }

  /** @internal Forgets the computation waiting for the next frame. */
  unschedule() {
    this.pending = null;
    cancelAnimationFrame(this.frame);
  }

  /** @internal The handle under the pointer (highlighted; the cursor says it can be grabbed). */
  setHover(/** @type {number} */ k) {
    if (k === this.hover) return;
    this.hover = k;
    this.viewer.canvas.classList.toggle('rl-grab', k >= 0);
    this.viewer.requestRender();
  }

  /** Selects handle `k` (ending a run of key moves on another); `picked`: a press on a blob takes it. */
  select(/** @type {number} */ k, picked = false) {
    this.keys.end();
    this.selected = k;
    this.picked = picked;
    this.hooks.say(this.describe(k));
    this.viewer.requestRender();
    this.hooks.changed();
  }

  // —— words and pictures (edit/marks.js) ——————————————————————————————————————

  /** A handle in words: "ruling 5, end b: 1.20, −0.40, 3.00". */
  describe(/** @type {number} */ k) {
    return this.marks.describe(k);
  }

  /** The name of a handle ("ruling 5, end b"). */
  nameOf(/** @type {Handle} */ handle) {
    return this.marks.nameOf(handle);
  }

  /** Draws the handles over the view after a frame. @param {ArrayLike<number>} viewProj */
  place(viewProj) {
    this.marks.place(viewProj);
  }

  /** Forgets timers and listeners' work in progress. */
  dispose() {
    this.cancel();
    this.pick.close();
    this.marks.dispose();
  }
}

/** The bounding box of the handles' points (input coordinates). */
function boxOf(/** @type {import('../scene.js').HandleSet[]} */ sets) {
  const min = [Infinity, Infinity, Infinity],
    max = [-Infinity, -Infinity, -Infinity];
  for (const { points } of sets)
    for (let i = 0; i + 2 < points.length; i += 3)
      for (let k = 0; k < 3; k++) {
        if (points[i + k] < min[k]) min[k] = points[i + k];
        if (points[i + k] > max[k]) max[k] = points[i + k];
      }
  return { min, max };
}
