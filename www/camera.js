// An orbit camera around a target, z up: drag to orbit, right/shift-drag or two fingers to
// pan, wheel or pinch to zoom; keyboard: arrows orbit, shift+arrows pan, +/- zoom, F fits.
import { add, lookAt, multiply, perspective, scale, sub, cross, normalize, length } from './math.js';

export class OrbitCamera {
  constructor() {
    this.target = [0, 0, 0];
    this.distance = 10;
    this.yaw = 0.9;
    this.pitch = 0.35;
    this.fovY = (35 * Math.PI) / 180;
  }

  get eye() {
    const cp = Math.cos(this.pitch);
    const dir = [cp * Math.cos(this.yaw), cp * Math.sin(this.yaw), Math.sin(this.pitch)];
    return add(this.target, scale(dir, this.distance));
  }

  /** View-projection matrix for a viewport of this aspect ratio. */
  viewProj(aspect) {
    const near = this.distance / 100;
    const far = this.distance * 100;
    return multiply(perspective(this.fovY, aspect, near, far), lookAt(this.eye, this.target, [0, 0, 1]));
  }

  /** Frames a bounding box {min, max}. */
  fit({ min, max }) {
    if (!min.every(Number.isFinite)) return;
    this.target = scale(add(min, max), 0.5);
    const radius = Math.max(length(sub(max, min)) / 2, 1e-6);
    this.distance = (radius / Math.sin(this.fovY / 2)) * 1.05;
    this.home = { target: this.target, distance: this.distance, yaw: this.yaw, pitch: this.pitch };
  }

  /** Restores the last fitted view. */
  reset() {
    if (this.home) Object.assign(this, this.home);
  }

  orbit(dYaw, dPitch) {
    this.yaw += dYaw;
    this.pitch = Math.max(-1.55, Math.min(1.55, this.pitch + dPitch));
  }

  /** Pans by a fraction of the view height. */
  pan(dx, dy) {
    const eye = this.eye;
    const forward = normalize(sub(this.target, eye));
    const right = normalize(cross(forward, [0, 0, 1]));
    const up = cross(right, forward);
    const s = 2 * this.distance * Math.tan(this.fovY / 2);
    this.target = add(this.target, add(scale(right, -dx * s), scale(up, dy * s)));
  }

  zoom(factor) {
    this.distance = Math.max(1e-6, this.distance * factor);
  }

  /**
   * Connects mouse, touch and keyboard input on `element`; calls `changed()` after each move.
   * @param {HTMLElement} element
   */
  attach(element, changed) {
    const pointers = new Map();
    let last = null;
    element.addEventListener('pointerdown', (e) => {
      element.setPointerCapture(e.pointerId);
      pointers.set(e.pointerId, { x: e.clientX, y: e.clientY });
      last = null;
    });
    const end = (e) => {
      pointers.delete(e.pointerId);
      last = null;
    };
    element.addEventListener('pointerup', end);
    element.addEventListener('pointercancel', end);
    element.addEventListener('pointermove', (e) => {
      if (!pointers.has(e.pointerId)) return;
      const prev = pointers.get(e.pointerId);
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
        if (last) {
          this.zoom(last.span / Math.max(span, 1));
          this.pan((mid.x - last.mid.x) / h / 2, (mid.y - last.mid.y) / h / 2);
        }
        last = { mid, span };
      }
      changed();
    });
    element.addEventListener('contextmenu', (e) => e.preventDefault());
    element.addEventListener(
      'wheel',
      (e) => {
        e.preventDefault();
        this.zoom(Math.exp(Math.sign(e.deltaY) * Math.min(Math.abs(e.deltaY), 100) * 0.002));
        changed();
      },
      { passive: false },
    );
    element.addEventListener('keydown', (e) => {
      const step = 0.08;
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
      };
      if (actions[e.key]) {
        e.preventDefault();
        actions[e.key]();
        changed();
      }
    });
  }
}
