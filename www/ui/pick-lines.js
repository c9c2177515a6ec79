// Picking a line on screen, by pointer: hovering with a mouse (no button pressed) or a tap with a
// finger finds the line or point drawn nearest to it, within a few pixels — on screen only, among
// the projected lines or points, no geometry of its own. The 3D view and the Klein view mark
// the same line with it (stage/line-mark.js, stage/klein-pane.js).
import { toScreen } from '../edit/geometry.js';

/** How near the pointer must come to a line or a point to mark it (CSS px; a finger is ±4 px off). */
const NEAR = 14;
/** A tap: a press and release this close (CSS px) … */
const TAP_MOVE = 8;
/** … and this quick (ms). */
const TAP_TIME = 500;

/**
 * Listens on `canvas` for the pointer: hovering (a mouse, no button pressed) marks what
 * `nearest` finds, leaving unmarks, a tap marks (or unmarks, off every line).
 * @param {HTMLCanvasElement} canvas
 * @param {(x: number, y: number) => number} nearest   the line within NEAR px of (x, y), or −1
 * @param {(line: number | null) => void} mark
 */
export function pickLines(canvas, nearest, mark) {
  /** @type {{x: number, y: number, t: number} | null} */
  let down = null;
  const at = (/** @type {PointerEvent} */ e) => {
    const box = canvas.getBoundingClientRect();
    return /** @type {[number, number]} */ ([e.clientX - box.left, e.clientY - box.top]);
  };
  canvas.addEventListener('pointermove', (e) => {
    if (e.pointerType !== 'mouse' || e.buttons) return;
    const i = nearest(...at(e));
    mark(i < 0 ? null : i);
  });
  canvas.addEventListener('pointerleave', (e) => {
    if (e.pointerType === 'mouse') mark(null);
  });
  canvas.addEventListener('pointerdown', (e) => {
    down = { x: e.clientX, y: e.clientY, t: e.timeStamp };
  });
  canvas.addEventListener('pointerup', (e) => {
    const tap =
      down && Math.hypot(e.clientX - down.x, e.clientY - down.y) < TAP_MOVE && e.timeStamp - down.t < TAP_TIME;
    down = null;
    if (!tap || e.pointerType === 'mouse') return;
    const i = nearest(...at(e));
    mark(i < 0 ? null : i);
  });
}

/**
 * Listens on `canvas` for a click or a tap (any pointer: a press and release close together and
 * quick, not a drag) and hands its place, CSS px of the canvas, to `tapped`. A press another
 * listener took first (a handle's: edit/pointer.js stops it) is not one.
 * @param {HTMLCanvasElement} canvas
 * @param {(x: number, y: number) => void} tapped
 */
export function onTap(canvas, tapped) {
  /** @type {{x: number, y: number, t: number} | null} */
  let down = null;
  canvas.addEventListener('pointerdown', (e) => {
    down = e.button === 0 ? { x: e.clientX, y: e.clientY, t: e.timeStamp } : null;
  });
  canvas.addEventListener('pointerup', (e) => {
    const tap =
      down && Math.hypot(e.clientX - down.x, e.clientY - down.y) < TAP_MOVE && e.timeStamp - down.t < TAP_TIME;
    down = null;
    if (!tap) return;
    const box = canvas.getBoundingClientRect();
    tapped(e.clientX - box.left, e.clientY - box.top);
  });
}

/**
 * The point among `points` (3 floats each, projected by `viewProj` onto a view `w` × `h`)
 * nearest to (x, y) within NEAR px, or −1.
 * @param {Float32Array | Float64Array} points @param {Float32Array} viewProj
 * @param {number} w @param {number} h @param {number} x @param {number} y
 */
export function nearestPoint(points, viewProj, w, h, x, y) {
  let best = -1;
  let least = NEAR;
  for (let i = 0; 3 * i + 2 < points.length; i++) {
    const s = toScreen(viewProj, [points[3 * i], points[3 * i + 1], points[3 * i + 2]], w, h);
    const d = Math.hypot(s.x - x, s.y - y);
    if (s.visible && d < least) [best, least] = [i, d];
  }
  return best;
}

/**
 * The segment among `segments` (6 floats each, projected by `viewProj` onto a view `w` × `h`)
 * whose stroke passes nearest to (x, y) within NEAR px, or −1.
 * @param {Float32Array | Float64Array} segments @param {Float32Array} viewProj
 * @param {number} w @param {number} h @param {number} x @param {number} y
 */
export function nearestSegment(segments, viewProj, w, h, x, y) {
  const s = segments;
  let best = -1;
  let least = NEAR;
  for (let i = 0; 6 * i + 5 < s.length; i++) {
    const a = toScreen(viewProj, [s[6 * i], s[6 * i + 1], s[6 * i + 2]], w, h);
    const b = toScreen(viewProj, [s[6 * i + 3], s[6 * i + 4], s[6 * i + 5]], w, h);
    if (!a.visible || !b.visible) continue;
    // the distance on screen from (x, y) to the stroke a b
    const [dx, dy] = [b.x - a.x, b.y - a.y];
    const t = Math.max(0, Math.min(1, ((x - a.x) * dx + (y - a.y) * dy) / (dx * dx + dy * dy || 1)));
    const d = Math.hypot(a.x + t * dx - x, a.y + t * dy - y);
    if (d < least) [best, least] = [i, d];
  }
  return best;
}
