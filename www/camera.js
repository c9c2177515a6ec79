// An orbit camera around a target, z up: drag to orbit, right/shift-drag or two fingers to
// pan, wheel or pinch to zoom (a pinch zooms by the fingers' own ratio: spread them twice as far
// apart and the figure is twice as large); keyboard (while the view has focus): arrows orbit
// (J L I K too, which still turn it while the arrows move a point), shift+arrows pan, +/- zoom,
// F, 0 and Home back to the fitted view.
import { add, lookAt, multiply, perspective, scale, sub, cross, normalize, length } from './math.js';
import { CAMERA_NEAREST, PITCH_LIMIT } from './limits.js';

/**
 * Left on the screen of a camera turned by `yaw` about z (z up, looking at its target from the
 * direction (cos yaw, sin yaw, ·)): the world direction (sin yaw, −cos yaw, 0).
 * @param {number} yaw
 */
export function screenLeft(yaw) {
  return [Math.sin(yaw), -Math.cos(yaw), 0];
}

export class OrbitCamera {
  constructor() {
    this.target = [0, 0, 0];
    this.distance = 10;
    this.yaw = 0.9;
    this.pitch = 0.35;
    this.fovY = (35 * Math.PI) / 180;
    /** @type {{target: number[], distance: number, yaw: number, pitch: number} | null} */
    this.home = null;
  }

  get eye() {
    const cp = Math.cos(this.pitch);
    const dir = [cp * Math.cos(this.yaw), cp * Math.sin(this.yaw), Math.sin(this.pitch)];
    return add(this.target, scale(dir, this.distance));
  }

  /** View-projection matrix for a viewport of this aspect ratio. */
  viewProj(/** @type {number} */ aspect) {
    const near = this.distance / 100;
    const far = this.distance * 100;
    return multiply(perspective(this.fovY, aspect, near, far), lookAt(this.eye, this.target, [0, 0, 1]));
  }

  /**
   * Frames a bounding box {min, max} in a viewport of `aspect` (width/height): the box's
   * bounding sphere fits both the height and the width, so a portrait phone shows it whole.
   * @param {{min: number[], max: number[]}} box
   * @param {number} [aspect]
   */
  fit({ min, max }, aspect = 1, { top = 0, bottom = 0 } = {}) {
    if (!min.every(Number.isFinite) || !max.every(Number.isFinite)) return;
    this.target = scale(add(min, max), 0.5);
    const radius = Math.max(length(sub(max, min)) / 2, CAMERA_NEAREST);
    // `top` and `bottom` (fractions of the height) are covered by the legend and the toolbar:
    // the sphere fits the band between them, and its centre moves to the band's centre
    const band = Math.max(0.3, 1 - top - bottom);
    const half = Math.min(
      Math.atan(Math.tan(this.fovY / 2) * band),
      Math.atan(Math.tan(this.fovY / 2) * Math.max(aspect, 1e-3)),
    );
    this.distance = (radius / Math.sin(half)) * 1.04;
    if (band < 1) this.pan(0, (top - bottom) / 2);
    this.home = { target: this.target, distance: this.distance, yaw: this.yaw, pitch: this.pitch };
  }

  /** Whether the camera is where the last fit put it. */
  atHome() {
    const h = this.home;
    return (
      !!h &&
      h.distance === this.distance &&
      h.yaw === this.yaw &&
      h.pitch === this.pitch &&
      h.target.every((x, i) => x === this.target[i])
    );
  }

  /** Restores the last fitted view. */
  reset() {
    if (this.home) Object.assign(this, this.home);
  }

  /** The camera as six numbers: yaw, pitch, distance, target x, y, z. */
  toArray() {
    return [this.yaw, this.pitch, this.distance, ...this.target];
  }

  /** Sets the camera from `toArray()`'s numbers. */
  fromArray(/** @type {number[]} */ [yaw, pitch, distance, ...target]) {
    Object.assign(this, {
      yaw,
      pitch: Math.max(-PITCH_LIMIT, Math.min(PITCH_LIMIT, pitch)),
      distance: Math.max(distance, CAMERA_NEAREST),
      target,
    });
  }

  orbit(/** @type {number} */ dYaw, /** @type {number} */ dPitch) {
    this.yaw += dYaw;
    this.pitch = Math.max(-PITCH_LIMIT, Math.min(PITCH_LIMIT, this.pitch + dPitch));
  }

  /** Pans by a fraction of the view height. */
  pan(/** @type {number} */ dx, /** @type {number} */ dy) {
    const eye = this.eye;
    const forward = normalize(sub(this.target, eye));
    const right = normalize(cross(forward, [0, 0, 1]));
    const up = cross(right, forward);
    const s = 2 * this.distance * Math.tan(this.fovY / 2);
    this.target = add(this.target, add(scale(right, -dx * s), scale(up, dy * s)));
  }

  zoom(/** @type {number} */ factor) {
    this.distance = Math.max(CAMERA_NEAREST, this.distance * factor);
  }

  /**
   * Connects mouse, touch and keyboard input on `element`; calls `changed(ended)` after each
   * move (`ended`: the gesture is over, e.g. to announce the result once).
   * @param {HTMLElement} element
   * @param {(ended: boolean) => void} changed
   */
  attach(element, changed) {
    /** @type {Map<number, {x: number, y: number}>} */
    const pointers = new Map();
    /** @type {{mid: {x: number, y: number}, span: number} | null} */
    let last = null;
    /** @type {{span: number, distance: number} | null} where a pinch began */
    let pinch = null;
    element.addEventListener('pointerdown', (e) => {
      element.setPointerCapture?.(e.pointerId);
      pointers.set(e.pointerId, { x: e.clientX, y: e.clientY });
      last = null;
      // a second finger: the pinch is measured from the fingers' span now
      const [p, q] = [...pointers.values()];
      pinch =
        pointers.size === 2 ? { span: Math.max(Math.hypot(p.x - q.x, p.y - q.y), 1), distance: this.distance } : null;
    });
    const end = (/** @type {PointerEvent} */ e) => {
      const was = pointers.delete(e.pointerId);
      last = null;
      pinch = null;
      if (was && pointers.size === 0) changed(true);
    };
    element.addEventListener('pointerup', end);
    element.addEventListener('pointercancel', end);
    element.addEventListener('pointermove', (e) => {
      const prev = pointers.get(e.pointerId);
      if (!prev) return;
      pointers.set(e.pointerId, { x: e.clientX, y: e.clientY });
      const h = element.clientHeight || 1;
      if (pointers.size === 1) {
        const dx = (e.clientX - prev.x) / h;
        const dy = (e.clientY - prev.y) / h;
        if (e.buttons & 2 || e.shiftKey) this.pan(dx, dy);
        else this.orbit(-dx * 3, dy * 3);
      } else {
        const [p, q] = [...pointers.values()];
        const mid = { x: (p.x + q.x) / 2, y: (p.y + q.y) / 2 };
        const span = Math.hypot(p.x - q.x, p.y - q.y);
        // the distance from where the pinch began, by the ratio of the fingers' spans (not a
        // product of per-event factors, which drifts)
        pinch ??= { span: Math.max(span, 1), distance: this.distance };
        this.distance = Math.max(CAMERA_NEAREST, (pinch.distance * pinch.span) / Math.max(span, 1));
        if (last) this.pan((mid.x - last.mid.x) / h / 2, (mid.y - last.mid.y) / h / 2);
        last = { mid, span };
      }
      changed(false);
    });
    element.addEventListener('contextmenu', (e) => e.preventDefault());
    let wheelEnd = 0;
    element.addEventListener(
      'wheel',
      (e) => {
        e.preventDefault();
        this.zoom(Math.exp(Math.sign(e.deltaY) * Math.min(Math.abs(e.deltaY), 100) * 0.002));
        changed(false);
        clearTimeout(wheelEnd);
        wheelEnd = window.setTimeout(() => changed(true), 300);
      },
      { passive: false },
    );
    element.addEventListener('keydown', (e) => {
      const step = 0.08;
      /** @type {Record<string, () => void>} */
      const actions = {
        ArrowLeft: () => (e.shiftKey ? this.pan(-step, 0) : this.orbit(step, 0)),
        ArrowRight: () => (e.shiftKey ? this.pan(step, 0) : this.orbit(-step, 0)),
        ArrowUp: () => (e.shiftKey ? this.pan(0, -step) : this.orbit(0, step)),
        ArrowDown: () => (e.shiftKey ? this.pan(0, step) : this.orbit(0, -step)),
        '+': () => this.zoom(0.9),
        '=': () => this.zoom(0.9),
        '-': () => this.zoom(1 / 0.9),
        f: () => this.reset(),
        F: () => this.reset(),
        0: () => this.reset(),
        Home: () => this.reset(),
        // letters that turn the view whatever the arrows do (while editing they move a point)
        j: () => this.orbit(step, 0),
        l: () => this.orbit(-step, 0),
        i: () => this.orbit(0, step),
        k: () => this.orbit(0, -step),
      };
      if (actions[e.key] && !e.ctrlKey && !e.metaKey && !e.altKey) {
        e.preventDefault();
        actions[e.key]();
        changed(true);
      }
    });
  }
}
