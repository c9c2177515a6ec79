// A handle under the pointer or a finger: a press within reach grabs it before the camera does
// (capture phase) and a drag moves it — in the plane facing the viewer, with Shift along its own
// line, with Alt along the input's z-axis, or as the mode buttons say — snapped by the core onto
// what is near (edit/snap.js). A press held still for a moment (a long press) shows the handle's
// coordinates and makes the drag fine: the handle then follows at a fraction of the pointer's
// speed. A press on handles that overlap on screen offers them as a short list (edit/pick.js); a
// tap selects a handle. A drag elsewhere still turns the camera; a second finger ends the drag
// and pinches.
import { inputOf, sameInput } from './input.js';
import { toScreen } from './geometry.js';
import { constraintOf } from './snap.js';
import { normalize, sub } from '../math.js';
import {
  DRAG_SLOP,
  FINE_DRAG,
  HANDLE_OVERLAP,
  HANDLE_REACH,
  HANDLE_REACH_COARSE,
  LONG_PRESS,
  SNAP_REACH,
  SNAP_REACH_COARSE,
} from '../limits.js';

/** Whether the main pointer is coarse (a finger). */
function coarse() {
  return typeof matchMedia === 'function' && matchMedia('(pointer: coarse)').matches;
}

export class PointerInput {
  /** @param {import('./editor.js').Editor} editor */
  constructor(editor) {
    this.editor = editor;
    const view = editor.view;
    view.addEventListener('pointerdown', (e) => this.down(e), { capture: true });
    view.addEventListener('pointermove', (e) => this.move(e), { capture: true });
    view.addEventListener('pointerup', (e) => this.up(e, false), { capture: true });
    view.addEventListener('pointercancel', (e) => this.up(e, true), { capture: true });
    view.addEventListener('pointerleave', () => editor.setHover(-1));
    /** @type {{x: number, y: number, handle: {x: number, y: number}} | null} where a fine drag was anchored */
    this.fineAt = null;
  }

  /** @internal The pointer in CSS px of the view, and the view's size. */
  local(/** @type {{clientX: number, clientY: number}} */ e) {
    const r = this.editor.viewer.canvas.getBoundingClientRect();
    return { x: e.clientX - r.left, y: e.clientY - r.top, w: r.width || 1, h: r.height || 1 };
  }

  /** @internal Whether the pointer is a finger (a coarse reach). */
  finger(/** @type {{pointerType?: string}} */ e) {
    return e.pointerType === 'touch' || coarse();
  }

  /**
   * @internal The handles within reach of a pointer event, nearest first, with their places on
   * screen (CSS px of the view).
   */
  within(/** @type {PointerEvent} */ e) {
    const editor = this.editor;
    if (!editor.active) return [];
    const { x, y, w, h } = this.local(e);
    const m = editor.viewer.camera.viewProj(w / h);
    const reach = this.finger(e) ? HANDLE_REACH_COARSE : HANDLE_REACH;
    return editor
      .handles()
      .map((handle, k) => ({ k, ...toScreen(m, handle.world, w, h) }))
      .filter((s) => s.visible && Math.hypot(s.x - x, s.y - y) <= reach)
      .map((s) => ({ ...s, d: Math.hypot(s.x - x, s.y - y) }))
      .sort((a, b) => a.d - b.d);
  }

  /** @internal The handle within reach of a pointer event, or -1. */
  pick(/** @type {PointerEvent} */ e) {
    return this.within(e)[0]?.k ?? -1;
  }

  /** @internal */
  down(/** @type {PointerEvent} */ e) {
    const editor = this.editor;
    if (editor.drag) {
      // a second finger: the drag ends as it stands, and the camera has the new finger
      if (e.pointerId !== editor.drag.pointer) this.finish();
      return;
    }
    if (e.button !== 0 || e.target !== editor.viewer.canvas) return;
    const near = this.within(e);
    if (!near.length) {
      editor.pick.close();
      return;
    }
    e.stopImmediatePropagation();
    e.preventDefault();
    // handles on top of each other: the one chosen from the list (or by the keyboard), else the list
    const chosen = editor.picked ? near.find((s) => s.k === editor.selected) : undefined;
    if (!chosen && near.length > 1 && Math.hypot(near[0].x - near[1].x, near[0].y - near[1].y) < HANDLE_OVERLAP) {
      const { x, y } = this.local(e);
      editor.pick.open(
        near.map((s) => s.k),
        x,
        y,
      );
      return;
    }
    editor.pick.close();
    const k = (chosen ?? near[0]).k;
    // (a pointer the browser does not know, e.g. a synthetic one, cannot be captured: the drag goes on)
    try {
      editor.viewer.canvas.setPointerCapture?.(e.pointerId);
    } catch {}
    editor.viewer.canvas.focus({ preventScroll: true });
    editor.keys.end();
    const handle = editor.handles()[k];
    const { x, y } = this.local(e);
    const at = chosen ?? near[0];
    editor.selected = k;
    editor.drag = {
      pointer: e.pointerId,
      handle: k,
      before: editor.hooks.current(),
      // a drag starts from what is drawn: the core's form of the input
      working: inputOf(editor.sets),
      initial: inputOf(editor.sets),
      start: handle.point,
      grab: { x: e.clientX, y: e.clientY },
      offset: { x: at.x - x, y: at.y - y },
      mode: this.modeOf(e),
      moved: false,
      fine: false,
      timer: window.setTimeout(() => this.longPress(), LONG_PRESS),
      touch: e.pointerType === 'touch',
      snap: null,
      held: null,
    };
    this.fineAt = null;
    editor.snapper.begin(k);
    editor.live.begin();
    editor.setHover(k);
    editor.hooks.changed();
  }

  /** @internal A press held still: the handle's coordinates beside it, and a fine drag from here. */
  longPress() {
    const editor = this.editor;
    const drag = editor.drag;
    if (!drag || drag.moved) return;
    drag.fine = true;
    const { w, h } = this.local({ clientX: 0, clientY: 0 });
    const s = toScreen(editor.viewer.camera.viewProj(w / h), editor.handles()[drag.handle].world, w, h);
    const pointer = this.local({ clientX: drag.grab.x, clientY: drag.grab.y });
    this.fineAt = { x: pointer.x, y: pointer.y, handle: { x: s.x, y: s.y } };
    editor.marks.showTip(drag.handle);
    editor.hooks.say(editor.hooks.i18n().t('edit.fine', { percent: Math.round(FINE_DRAG * 100) }));
  }

  /** @internal The mode a pointer event asks for: Shift along the line, Alt vertical, else the buttons'. */
  modeOf(/** @type {{shiftKey: boolean, altKey: boolean}} */ e) {
    return e.shiftKey ? 'line' : e.altKey ? 'vertical' : this.editor.mode;
  }

  /** @internal Where the pointer asks the handle to be on screen (CSS px of the view). */
  aim(/** @type {{clientX: number, clientY: number}} */ e) {
    const drag = /** @type {import('./editor.js').Drag} */ (this.editor.drag);
    const { x, y } = this.local(e);
    const fine = this.fineAt;
    if (drag.fine && fine)
      return { x: fine.handle.x + (x - fine.x) * FINE_DRAG, y: fine.handle.y + (y - fine.y) * FINE_DRAG };
    return { x: x + drag.offset.x, y: y + drag.offset.y };
  }

  /** @internal Starts the drag's geometry afresh where the handle is now (a new mode). */
  rebase(/** @type {{clientX: number, clientY: number}} */ e) {
    const editor = this.editor;
    const drag = /** @type {import('./editor.js').Drag} */ (editor.drag);
    const handle = editor.handles()[drag.handle];
    const { x, y, w, h } = this.local(e);
    const s = toScreen(editor.viewer.camera.viewProj(w / h), handle.world, w, h);
    drag.start = handle.point;
    drag.offset = { x: s.x - x, y: s.y - y };
    if (this.fineAt) this.fineAt = { x, y, handle: { x: s.x, y: s.y } };
  }

  /** @internal */
  move(/** @type {PointerEvent} */ e) {
    const editor = this.editor;
    const drag = editor.drag;
    if (!drag) {
      if (e.buttons === 0 && e.pointerType !== 'touch') editor.setHover(this.pick(e));
      return;
    }
    if (e.pointerId !== drag.pointer) return;
    e.stopImmediatePropagation();
    if (!drag.moved && Math.hypot(e.clientX - drag.grab.x, e.clientY - drag.grab.y) < DRAG_SLOP) return;
    if (!drag.moved) {
      drag.moved = true;
      clearTimeout(drag.timer);
      editor.hooks.changed();
    }
    const mode = this.modeOf(e);
    if (mode !== drag.mode) {
      drag.mode = mode;
      this.rebase(e);
    }
    this.place(this.aim(e), this.finger(e) ? SNAP_REACH_COARSE : SNAP_REACH);
  }

  /**
   * @internal Puts the dragged handle where the core places it for the pointer at (x, y) (CSS px
   * of the view), snapped within `reach`; a constraint of the exercise the core cannot keep is
   * said and lifted.
   */
  place(/** @type {{x: number, y: number}} */ { x, y }, /** @type {number} */ reach) {
    const editor = this.editor;
    const drag = /** @type {import('./editor.js').Drag} */ (editor.drag);
    const { camera } = editor.viewer;
    const forward = normalize(sub(camera.target, camera.eye));
    const handle = { ...editor.handles()[drag.handle], point: drag.start };
    let placed = editor.snapper.place(
      handle,
      drag.start,
      constraintOf(editor, handle, drag.mode, forward),
      x,
      y,
      reach,
    );
    const { t } = editor.hooks.i18n();
    if ((placed.held === 'degenerate' || placed.held === 'outside') && editor.rules.held(handle)) {
      editor.rules.lift(handle);
      editor.hooks.say(t('snap.lifted', { handle: editor.nameOf(handle) }));
      placed = editor.snapper.place(handle, drag.start, constraintOf(editor, handle, drag.mode, forward), x, y, reach);
    }
    if (placed.held !== drag.held && placed.held) editor.hooks.say(t(`snap.held.${placed.held}`));
    drag.held = placed.held;
    if (!placed.point) return;
    if (placed.snap?.name !== drag.snap?.name && placed.snap)
      editor.marks.sayNow(t('snap.onto', { name: placed.snap.name }));
    drag.snap = placed.snap;
    editor.put(drag.working, drag.handle, placed.point);
    // the computation first: its frame draws the moved handle with the geometry it makes (one
    // frame per move, not the handle's and then the geometry's)
    editor.schedule(drag.working);
    editor.marks.showTip(drag.handle);
    editor.marks.sayLater(drag.handle);
  }

  /** @internal */
  up(/** @type {PointerEvent} */ e, /** @type {boolean} */ cancelled) {
    const drag = this.editor.drag;
    if (!drag || e.pointerId !== drag.pointer) return;
    e.stopImmediatePropagation();
    if (cancelled) this.cancel(true);
    else this.finish();
  }

  /** Ends the drag, keeping where it put the handle (one step of undo); a tap selects the handle. */
  finish() {
    const editor = this.editor;
    const drag = editor.drag;
    if (!drag) return;
    clearTimeout(drag.timer);
    editor.marks.quiet();
    const { t } = editor.hooks.i18n();
    const said = [editor.describe(drag.handle), drag.snap && t('snap.onto', { name: drag.snap.name })]
      .filter(Boolean)
      .join('; ');
    editor.drag = null;
    this.fineAt = null;
    editor.unschedule();
    if (drag.moved && !sameInput(drag.working, drag.initial)) {
      // in an exercise the tip stays, its conditions (reached or not) written anew for the figure
      if (editor.live.outcomes().length) editor.marks.showTip(drag.handle);
      else editor.marks.hideTip();
      editor.record(drag.before);
      editor.hooks.apply(drag.working, true, said);
    } else if (!drag.moved) {
      // a tap (or a long press): the handle is selected, its coordinates stay beside it
      editor.select(drag.handle, true);
      editor.marks.showTip(drag.handle);
    } else editor.marks.hideTip();
    editor.hooks.changed();
    editor.viewer.requestRender();
  }

  /** Ends the drag; `undo` puts the handle back where it was (Escape, a cancelled touch). */
  cancel(/** @type {boolean} */ undo) {
    const editor = this.editor;
    const drag = editor.drag;
    if (!drag) return;
    if (!undo) return this.finish();
    clearTimeout(drag.timer);
    editor.drag = null;
    this.fineAt = null;
    editor.unschedule();
    editor.marks.hideTip();
    if (drag.moved) editor.hooks.apply(drag.before, true);
    editor.hooks.changed();
    editor.viewer.requestRender();
  }
}
