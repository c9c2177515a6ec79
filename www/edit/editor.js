// Editing a scene's input by its handles (scene.js: Editable, HandleSet): the pointer grabs the
// nearest handle within reach and drags it — in the plane through it orthogonal to the view, with
// Shift along its line, with Alt along the world z-axis, or as the mode buttons say — while a
// drag elsewhere still turns the camera; one finger drags a handle and a long press shows where it
// is; the keyboard steps through the handles and moves them. Every move goes to the stage, which
// hands the new input to the core and draws what comes back; one drag (or one run of key moves on
// a handle) is one step of undo, which restores the input bit for bit.
import { copyInput, inputOf, sameInput } from './input.js';
import { HandleMarks } from './marks.js';
import { clampTo, dragTo, editBox, invertRigid, nearest, pointerRay, toScreen, transformPoint } from './geometry.js';
import { normalize, sub, cross, add, scale } from '../math.js';
import { DRAG_SLOP, EDIT_BOX, HANDLE_REACH, HANDLE_REACH_COARSE, KEY_STEP, LONG_PRESS } from '../limits.js';

/** A run of key moves on one handle ends after this pause (ms): it is one step of undo. */
const KEY_RUN = 1000;

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
 * @property {() => void} changed   the editor's own state changed (mode, history): update buttons
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
    /** @type {number} the selected handle (keyboard), an index into handles() */
    this.selected = 0;
    /** @type {number} the handle under the pointer, or -1 */
    this.hover = -1;
    /**
     * The drag in progress.
     * @type {{pointer: number, handle: number, before: import('../scene.js').Input | null, working: import('../scene.js').Input, initial: import('../scene.js').Input,
     *   start: number[], offset: number[], mode: import('./geometry.js').MoveMode, moved: boolean, x: number, y: number,
     *   inverse: Float64Array | null, along: number[] | null, forward: number[], timer: number, touch: boolean} | null}
     */
    this.drag = null;
    /** @type {{handle: number, before: import('../scene.js').Input | null, working: import('../scene.js').Input, initial: import('../scene.js').Input, timer: number} | null} a run of key moves */
    this.keyRun = null;
    /** @type {import('../scene.js').Input | null} the input waiting for the next animation frame */
    this.pending = null;
    this.frame = 0;
    /** the handles drawn over the view, the tip beside one, and their words */
    this.marks = new HandleMarks(this);

    // before the camera (capture): a press on a handle is a drag, anywhere else the camera's
    view.addEventListener('pointerdown', (e) => this.down(e), { capture: true });
    view.addEventListener('pointermove', (e) => this.move(e), { capture: true });
    view.addEventListener('pointerup', (e) => this.up(e, false), { capture: true });
    view.addEventListener('pointercancel', (e) => this.up(e, true), { capture: true });
    view.addEventListener('pointerleave', () => this.setHover(-1));
    // while editing, the view's keys move handles (before the camera, which would turn on arrows)
    view.addEventListener(
      'keydown',
      (e) => {
        if (e.target === viewer.canvas && this.key(e)) e.stopImmediatePropagation();
      },
      { capture: true },
    );
  }

  /** Every handle, in order (set by set). */
  handles() {
    /** @type {Handle[]} */
    const out = [];
    const input = this.drag?.working ?? this.keyRun?.working ?? null;
    this.sets.forEach((set, s) => {
      const points = input?.[set.key] ?? set.points;
      for (let i = 0; 3 * i + 2 < points.length; i++) {
        const point = [points[3 * i], points[3 * i + 1], points[3 * i + 2]];
        out.push({ set: s, index: i, key: set.key, point, world: transformPoint(set.transform, point) });
      }
    });
    return out;
  }

  /**
   * The handles of a new build: their positions come from the core (unless a drag or a run of
   * key moves is in progress, whose own positions stay under the pointer).
   * @param {import('../scene.js').Editable | null | undefined} editable
   */
  show(editable) {
    this.sets = editable?.sets ?? [];
    this.from = editable?.from ?? this.from;
    if (!this.sets.length) this.setEditing(false);
    this.selected = Math.min(this.selected, Math.max(0, this.handles().length - 1));
    this.viewer.requestRender();
  }

  /** A new scene (or new settings of the built-in input): no history, handles kept in its box. */
  enter(/** @type {import('../scene.js').Editable | null | undefined} */ editable) {
    this.cancel();
    this.past = [];
    this.future = [];
    this.selected = 0;
    const box = editable?.sets.length ? boxOf(editable.sets) : null;
    this.box = box ? editBox(box, EDIT_BOX) : null;
    this.size = box ? Math.max(...box.max.map((b, k) => b - box.min[k]), 1e-6) : 1;
    this.show(editable);
    this.hooks.changed();
  }

  /** Whether the scene has handles and the reader may grab them. */
  get active() {
    return this.enabled && this.sets.length > 0;
  }

  /** Keyboard editing on or off (every handle shown, arrows move the selected one). */
  setEditing(/** @type {boolean} */ on) {
    on = on && this.active;
    if (on === this.editing) return;
    this.endKeyRun();
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

  /** Whether an undo step exists. */
  get canUndo() {
    return this.past.length > 0 || !!this.drag?.moved || !!this.keyRun;
  }
  get canRedo() {
    return this.future.length > 0;
  }

  /** Takes back the last step (a drag, a run of key moves, a reset of the input). */
  undo() {
    this.cancelDrag(false);
    this.endKeyRun();
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
    this.cancelDrag(false);
    this.endKeyRun();
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
    this.cancelDrag(false);
    this.endKeyRun();
    const now = this.hooks.current();
    const base = this.hooks.base?.() ?? null;
    if (sameInput(now, base)) return;
    this.record(now);
    this.hooks.apply(base && copyInput(base), true, this.hooks.i18n().t('edit.restored'));
  }

  /** Replaces the input (<ruled-view>'s `data`), as one step of undo. */
  replace(/** @type {import('../scene.js').Input} */ input) {
    this.cancelDrag(false);
    this.endKeyRun();
    this.record(this.hooks.current());
    this.hooks.apply(copyInput(input), true);
  }

  /** @internal A step of undo: the input before it. */
  record(/** @type {import('../scene.js').Input | null} */ before) {
    this.past.push(before);
    this.future = [];
    this.hooks.changed();
  }

  /** Stops whatever is in progress, keeping what it did. */
  cancel() {
    this.cancelDrag(false);
    this.endKeyRun();
  }

  // —— pointer ————————————————————————————————————————————————————————————————

  /** @internal The handle within reach of a pointer event, or -1. */
  pick(/** @type {PointerEvent} */ e) {
    if (!this.active) return -1;
    const { x, y, w, h } = this.local(e);
    const m = this.viewer.camera.viewProj(w / h);
    const points = this.handles().map((p) => toScreen(m, p.world, w, h));
    const reach = e.pointerType === 'touch' || coarse() ? HANDLE_REACH_COARSE : HANDLE_REACH;
    return nearest(points, x, y, reach);
  }

  /** @internal The pointer in CSS px of the view, and the view's size. */
  local(/** @type {{clientX: number, clientY: number}} */ e) {
    const r = this.viewer.canvas.getBoundingClientRect();
    return { x: e.clientX - r.left, y: e.clientY - r.top, w: r.width || 1, h: r.height || 1 };
  }

  /** @internal */
  down(/** @type {PointerEvent} */ e) {
    if (this.drag) {
      // a second finger: the drag ends as it stands, and the camera has the new finger
      if (e.pointerId !== this.drag.pointer) this.finishDrag();
      return;
    }
    if (e.button !== 0 || e.target !== this.viewer.canvas) return;
    const k = this.pick(e);
    if (k < 0) return;
    e.stopImmediatePropagation();
    e.preventDefault();
    // (a pointer the browser does not know, e.g. a synthetic one, cannot be captured: the drag goes on)
    try {
      this.viewer.canvas.setPointerCapture?.(e.pointerId);
    } catch {}
    this.viewer.canvas.focus({ preventScroll: true });
    this.endKeyRun();
    const before = this.hooks.current();
    const handle = this.handles()[k];
    const set = this.sets[handle.set];
    // a drag starts from what is drawn: the core's form of the input
    const working = inputOf(this.sets);
    const initial = inputOf(this.sets);
    this.selected = k;
    const { eye, target } = this.viewer.camera;
    this.drag = {
      pointer: e.pointerId,
      handle: k,
      before,
      working,
      initial,
      start: handle.world,
      offset: [0, 0, 0],
      mode: this.modeOf(e),
      moved: false,
      x: e.clientX,
      y: e.clientY,
      inverse: set.transform ? invertRigid(set.transform) : null,
      along: this.alongOf(handle),
      forward: normalize(sub(target, eye)),
      timer: 0,
      touch: e.pointerType === 'touch',
    };
    this.rebase(e);
    if (this.drag.touch) this.drag.timer = window.setTimeout(() => this.showTip(k), LONG_PRESS);
    this.setHover(k);
    this.hooks.changed();
  }

  /** @internal The mode a pointer event asks for: Shift along the line, Alt vertical, else the buttons'. */
  modeOf(/** @type {{shiftKey: boolean, altKey: boolean}} */ e) {
    return e.shiftKey ? 'line' : e.altKey ? 'vertical' : this.mode;
  }

  /** @internal The direction of a handle's line (its other end's way), in world coordinates, or null. */
  alongOf(/** @type {Handle} */ handle) {
    const set = this.sets[handle.set];
    if (set.shape !== 'pairs') return null;
    const other = this.handles().find((h) => h.set === handle.set && h.index === (handle.index ^ 1));
    return other ? sub(other.world, handle.world) : null;
  }

  /** @internal Starts the drag's geometry afresh where the handle is now (a new mode, the first move). */
  rebase(/** @type {{clientX: number, clientY: number}} */ e) {
    const drag = /** @type {NonNullable<Editor['drag']>} */ (this.drag);
    const handle = this.handles()[drag.handle];
    drag.start = handle.world;
    const hit = this.target(e, [0, 0, 0]);
    drag.offset = hit ? sub(drag.start, hit) : [0, 0, 0];
  }

  /** @internal Where the pointer puts the dragged handle (world coordinates), or null. */
  target(/** @type {{clientX: number, clientY: number}} */ e, /** @type {number[]} */ offset) {
    const drag = /** @type {NonNullable<Editor['drag']>} */ (this.drag);
    const { x, y, w, h } = this.local(e);
    const ray = pointerRay(this.viewer.camera, x, y, w, h);
    const along = drag.mode === 'line' ? drag.along : null;
    const p = dragTo(drag.mode === 'line' && !along ? 'view' : drag.mode, ray, drag.start, drag.forward, along);
    return p?.every(Number.isFinite) ? add(p, offset) : null;
  }

  /** @internal */
  move(/** @type {PointerEvent} */ e) {
    const drag = this.drag;
    if (!drag) {
      if (e.buttons === 0 && e.pointerType !== 'touch') this.setHover(this.pick(e));
      return;
    }
    if (e.pointerId !== drag.pointer) return;
    e.stopImmediatePropagation();
    if (!drag.moved && Math.hypot(e.clientX - drag.x, e.clientY - drag.y) < DRAG_SLOP) return;
    if (!drag.moved) {
      drag.moved = true;
      clearTimeout(drag.timer);
      this.hooks.changed();
    }
    const mode = this.modeOf(e);
    if (mode !== drag.mode) {
      drag.mode = mode;
      this.rebase(e);
    }
    const world = this.target(e, drag.offset);
    if (!world) return;
    this.put(drag.working, drag.handle, world, drag.inverse);
    this.showTip(drag.handle);
    this.sayLater(drag.handle);
    this.schedule(drag.working);
  }

  /** @internal */
  up(/** @type {PointerEvent} */ e, /** @type {boolean} */ cancelled) {
    const drag = this.drag;
    if (!drag || e.pointerId !== drag.pointer) return;
    e.stopImmediatePropagation();
    if (cancelled) this.cancelDrag(true);
    else this.finishDrag();
  }

  /** @internal Ends the drag, keeping where it put the handle (one step of undo). */
  finishDrag() {
    const drag = this.drag;
    if (!drag) return;
    clearTimeout(drag.timer);
    this.marks.quiet();
    const said = this.describe(drag.handle);
    this.drag = null;
    this.pending = null;
    cancelAnimationFrame(this.frame);
    this.marks.hideTip();
    if (drag.moved && !sameInput(drag.working, drag.initial)) {
      this.record(drag.before);
      this.hooks.apply(drag.working, true, said);
    }
    this.hooks.changed();
    this.viewer.requestRender();
  }

  /** @internal Ends the drag; `undo` puts the handle back where it was (Escape, a cancelled touch). */
  cancelDrag(/** @type {boolean} */ undo) {
    const drag = this.drag;
    if (!drag) return;
    if (!undo) return this.finishDrag();
    clearTimeout(drag.timer);
    this.drag = null;
    this.pending = null;
    cancelAnimationFrame(this.frame);
    this.marks.hideTip();
    if (drag.moved) this.hooks.apply(drag.before, true);
    this.hooks.changed();
    this.viewer.requestRender();
  }

  /**
   * @internal Puts handle `k` of `input` at the world point `world` (through the set's inverse
   * transform, into the box).
   */
  put(
    /** @type {import('../scene.js').Input} */ input,
    /** @type {number} */ k,
    /** @type {number[]} */ world,
    /** @type {Float64Array | null} */ inverse,
  ) {
    const handle = this.handles()[k];
    let p = inverse ? transformPoint(inverse, world) : world;
    if (this.box) p = clampTo(p, this.box);
    if (!p.every(Number.isFinite)) return;
    const points = input[handle.key];
    const at = 3 * handle.index;
    // a tool's tip carries its axis end along (the tool moves); the axis end alone turns it
    if (this.sets[handle.set].carry && handle.index % 2 === 0) {
      const box = this.box;
      const moved = [0, 1, 2].map((c) => points[at + 3 + c] + p[c] - points[at + c]);
      if (box && moved.some((x, c) => x < box.min[c] || x > box.max[c])) return;
      points.set(moved, at + 3);
    }
    points.set(p, at);
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
    });
  }

  /** @internal The handle under the pointer (highlighted; the cursor says it can be grabbed). */
  setHover(/** @type {number} */ k) {
    if (k === this.hover) return;
    this.hover = k;
    this.viewer.canvas.classList.toggle('rl-grab', k >= 0);
    this.viewer.requestRender();
  }

  // —— keyboard ———————————————————————————————————————————————————————————————

  /**
   * A key pressed on the view while editing; true when it was the editor's.
   * @param {KeyboardEvent} e
   */
  key(e) {
    if (!this.editing) return false;
    const count = this.handles().length;
    if (!count) return false;
    const { camera } = this.viewer;
    const forward = normalize(sub(camera.target, camera.eye));
    const right = normalize(cross(forward, [0, 0, 1]));
    const up = cross(right, forward);
    const step = this.size * KEY_STEP * (e.shiftKey ? 0.1 : 1);
    /** @type {Record<string, number[]>} */
    const moves = {
      ArrowLeft: scale(right, -step),
      ArrowRight: scale(right, step),
      ArrowUp: scale(up, step),
      ArrowDown: scale(up, -step),
      PageUp: scale(forward, step),
      PageDown: scale(forward, -step),
    };
    if (e.ctrlKey || e.metaKey || e.altKey) return false;
    if (e.key === 'Tab' || e.key === ']' || e.key === '[') {
      const back = e.key === '[' || (e.key === 'Tab' && e.shiftKey);
      this.select((this.selected + (back ? count - 1 : 1)) % count);
    } else if (moves[e.key]) {
      this.nudge(moves[e.key]);
    } else if (e.key === 'Escape') {
      if (this.keyRun) this.cancelKeyRun();
      else this.setEditing(false);
    } else if (e.key === 'Enter') {
      this.endKeyRun();
    } else return false;
    e.preventDefault();
    return true;
  }

  /** Selects handle `k` (ending a run of key moves on another). */
  select(/** @type {number} */ k) {
    this.endKeyRun();
    this.selected = k;
    this.hooks.say(this.describe(k));
    this.viewer.requestRender();
    this.hooks.changed();
  }

  /** @internal Moves the selected handle by a world vector (a run of key moves is one undo step). */
  nudge(/** @type {number[]} */ by) {
    const k = this.selected;
    if (!this.keyRun) {
      const before = this.hooks.current();
      this.keyRun = { handle: k, before, working: inputOf(this.sets), initial: inputOf(this.sets), timer: 0 };
    }
    const run = this.keyRun;
    clearTimeout(run.timer);
    run.timer = window.setTimeout(() => this.endKeyRun(), KEY_RUN);
    const handle = this.handles()[k];
    const set = this.sets[handle.set];
    this.put(run.working, k, add(handle.world, by), set.transform ? invertRigid(set.transform) : null);
    this.sayLater(k);
    this.hooks.apply(copyInput(run.working), false);
    this.hooks.changed();
  }

  /** @internal Ends a run of key moves: one step of undo. */
  endKeyRun() {
    const run = this.keyRun;
    if (!run) return;
    clearTimeout(run.timer);
    this.marks.quiet();
    const said = this.describe(run.handle);
    this.keyRun = null;
    if (!sameInput(run.working, run.initial)) {
      this.record(run.before);
      this.hooks.apply(run.working, true, said);
    }
  }

  /** @internal Escape during a run of key moves: the handle goes back. */
  cancelKeyRun() {
    const run = this.keyRun;
    if (!run) return;
    clearTimeout(run.timer);
    this.keyRun = null;
    this.hooks.apply(run.before, true, this.hooks.i18n().t('edit.cancelled'));
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

  /** @internal Says where handle `k` is, at most once a second (the last position wins). */
  sayLater(/** @type {number} */ k) {
    this.marks.sayLater(k);
  }

  /** @internal Shows the coordinates of handle `k` beside it (a long press, a drag). */
  showTip(/** @type {number} */ k) {
    this.marks.showTip(k);
  }

  /** Draws the handles over the view after a frame. @param {ArrayLike<number>} viewProj */
  place(viewProj) {
    this.marks.place(viewProj);
  }

  /** Forgets timers and listeners' work in progress. */
  dispose() {
    this.cancel();
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

/** Whether the main pointer is coarse (a finger). */
function coarse() {
  return typeof matchMedia === 'function' && matchMedia('(pointer: coarse)').matches;
}
