// Playing a parameter, like GeoGebra's animation button: a continuous parameter sweeps back
// and forth between its ends, a stepped one counts up and starts over; speed and single steps
// are offered. Respects prefers-reduced-motion (no autoplay; playing stays possible).
import { ROUNDING } from '../limits.js';

/** Seconds for one sweep across a continuous range at speed 1. */
const SWEEP = 4;
/** Seconds per step of a stepped (integer) parameter at speed 1. */
const STEP_TIME = 0.8;

export class Player {
  /**
   * @param {(key: string, value: number) => void} set   applies a value
   */
  constructor(set) {
    this.set = set;
    /** @type {import('../scene.js').Param | null} */
    this.param = null;
    this.value = 0;
    this.direction = 1;
    this.speed = 1;
    this.frame = 0;
    this.last = 0;
    this.accumulated = 0;
  }

  /** Whether `p` moves in whole steps (an integer slider). */
  static stepped(/** @type {import('../scene.js').Param} */ p) {
    return Number.isInteger(p.step ?? 0) && (p.step ?? 0) >= 1;
  }

  /** Whether the user asked for less motion (no autoplay then). */
  static reducedMotion() {
    return typeof matchMedia === 'function' && matchMedia('(prefers-reduced-motion: reduce)').matches;
  }

  get playing() {
    return this.frame !== 0;
  }

  /** Starts playing `p` from `value`. */
  play(/** @type {import('../scene.js').Param} */ p, /** @type {number} */ value) {
    this.stop();
    this.param = p;
    this.value = value;
    this.last = performance.now();
    this.accumulated = 0;
    const tick = (/** @type {number} */ now) => {
      const dt = Math.min((now - this.last) / 1000, 0.25);
      this.last = now;
      this.advance(dt);
      this.frame = requestAnimationFrame(tick);
    };
    this.frame = requestAnimationFrame(tick);
  }

  stop() {
    cancelAnimationFrame(this.frame);
    this.frame = 0;
  }

  /** One step forward (a slider step for stepped parameters, 1/20 of the range otherwise). */
  step(/** @type {import('../scene.js').Param} */ p, /** @type {number} */ value) {
    this.param = p;
    this.value = value;
    const min = /** @type {number} */ (p.min),
      max = /** @type {number} */ (p.max);
    const delta = Player.stepped(p) ? /** @type {number} */ (p.step) : (max - min) / 20;
    let next = value + delta;
    if (next > max + ROUNDING) next = min;
    this.value = Player.stepped(p) ? next : Number(next.toFixed(6));
    this.set(p.key, this.value);
  }

  /** Advances the playing parameter by `dt` seconds. */
  advance(/** @type {number} */ dt) {
    const p = this.param;
    if (!p) return;
    const min = /** @type {number} */ (p.min),
      max = /** @type {number} */ (p.max);
    if (Player.stepped(p)) {
      this.accumulated += dt * this.speed;
      if (this.accumulated < STEP_TIME) return;
      this.accumulated = 0;
      this.value =
        this.value + /** @type {number} */ (p.step) > max ? min : this.value + /** @type {number} */ (p.step);
    } else {
      let v = this.value + (this.direction * dt * this.speed * (max - min)) / SWEEP;
      if (v >= max) [v, this.direction] = [max, -1];
      if (v <= min) [v, this.direction] = [min, 1];
      this.value = v;
    }
    this.set(p.key, this.value);
  }
}
