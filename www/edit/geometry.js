// Where a handle is on screen and where a drag puts it: the camera's projection of a handle, the
// ray through a pointer, and the three ways a handle moves — in the plane through it orthogonal
// to the view, along the line it belongs to (a ruling, a tool axis), along the world z-axis —
// kept inside the scene's box. This is the camera's geometry (the page's), not the paper's: no
// formula of the core is repeated here.
import { add, cross, length, normalize, scale, sub } from '../math.js';

/** @typedef {[number, number, number]} Vec3 */
/** @typedef {{origin: number[], dir: number[]}} Ray */
/** @typedef {'view' | 'line' | 'vertical'} MoveMode */

const dot = (/** @type {number[]} */ a, /** @type {number[]} */ b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

/**
 * A point moved by a 4 × 4 column-major matrix (a rigid motion; no perspective).
 * @param {ArrayLike<number> | null | undefined} m
 * @param {number[]} p
 * @returns {number[]}
 */
export function transformPoint(m, p) {
  if (!m) return p;
  return [0, 1, 2].map((k) => m[k] * p[0] + m[4 + k] * p[1] + m[8 + k] * p[2] + m[12 + k]);
}

/**
 * The inverse of a rigid motion given as a 4 × 4 column-major matrix: the transposed rotation
 * and the translation taken back.
 * @param {ArrayLike<number>} m
 * @returns {Float64Array}
 */
export function invertRigid(m) {
  const r = new Float64Array(16);
  for (let i = 0; i < 3; i++) for (let j = 0; j < 3; j++) r[4 * j + i] = m[4 * i + j];
  for (let i = 0; i < 3; i++) r[12 + i] = -(r[i] * m[12] + r[4 + i] * m[13] + r[8 + i] * m[14]);
  r[15] = 1;
  return r;
}

/**
 * Screen position (CSS px from the view's top left) of a world point under the view-projection
 * `m` of a view `w` × `h` CSS px; `visible` false behind the camera.
 * @param {ArrayLike<number>} m
 * @param {number[]} p
 * @param {number} w
 * @param {number} h
 */
export function toScreen(m, p, w, h) {
  const cw = m[3] * p[0] + m[7] * p[1] + m[11] * p[2] + m[15];
  return {
    x: (((m[0] * p[0] + m[4] * p[1] + m[8] * p[2] + m[12]) / cw + 1) / 2) * w,
    y: ((1 - (m[1] * p[0] + m[5] * p[1] + m[9] * p[2] + m[13]) / cw) / 2) * h,
    visible: cw > 0,
  };
}

/**
 * The ray from the eye through a pointer at (x, y) CSS px of a view `w` × `h`, for an orbit
 * camera (eye, target, vertical field of view, z up), as camera.js projects.
 * @param {{eye: number[], target: number[], fovY: number}} camera
 * @param {number} x @param {number} y @param {number} w @param {number} h
 * @returns {Ray}
 */
export function pointerRay(camera, x, y, w, h) {
  const forward = normalize(sub(camera.target, camera.eye));
  const right = normalize(cross(forward, [0, 0, 1]));
  const up = cross(right, forward);
  const tan = Math.tan(camera.fovY / 2);
  const nx = (2 * x) / w - 1,
    ny = 1 - (2 * y) / h;
  const dir = normalize(add(forward, add(scale(right, nx * tan * (w / h)), scale(up, ny * tan))));
  return { origin: camera.eye, dir };
}

/**
 * Where the ray meets the plane through `point` with normal `normal`; null when it runs
 * parallel to the plane or meets it behind the eye.
 * @param {Ray} ray @param {number[]} point @param {number[]} normal
 */
export function onPlane(ray, point, normal) {
  const d = dot(ray.dir, normal);
  if (Math.abs(d) < 1e-12) return null;
  const t = dot(sub(point, ray.origin), normal) / d;
  return t > 0 ? add(ray.origin, scale(ray.dir, t)) : null;
}

/**
 * The point of the line through `point` with direction `dir` nearest to the ray (the pointer's
 * "shadow" on the line); null when the line runs along the ray.
 * @param {Ray} ray @param {number[]} point @param {number[]} dir
 */
export function onLine(ray, point, dir) {
  const u = normalize(dir);
  const w0 = sub(point, ray.origin);
  const b = dot(u, ray.dir);
  const denominator = 1 - b * b;
  if (!(length(u) > 0) || denominator < 1e-9) return null;
  const s = (b * dot(ray.dir, w0) - dot(u, w0)) / denominator;
  return add(point, scale(u, s));
}

/**
 * Where a drag puts a handle that was at `start` when the drag began.
 * @param {MoveMode} mode
 * @param {Ray} ray      through the pointer now
 * @param {number[]} start   the handle's world position at the start of the drag
 * @param {number[]} viewDir  the camera's forward direction (the plane's normal in "view" mode)
 * @param {number[] | null} along   the direction of the handle's line ("line" mode)
 * @returns {number[] | null}   null when the pointer gives no point (the handle stays)
 */
export function dragTo(mode, ray, start, viewDir, along) {
  if (mode === 'line' && along) return onLine(ray, start, along);
  if (mode === 'vertical') return onLine(ray, start, [0, 0, 1]);
  return onPlane(ray, start, viewDir);
}

/**
 * The box handles stay in: the scene's bounds scaled by `factor` about their centre (a cube
 * when the scene is flat in some direction).
 * @param {{min: number[], max: number[]}} bounds
 * @param {number} factor
 */
export function editBox({ min, max }, factor) {
  const centre = min.map((a, k) => (a + max[k]) / 2);
  const half = Math.max(...min.map((a, k) => (max[k] - a) / 2), 1e-6);
  const reach = factor * half;
  return { min: centre.map((c) => c - reach), max: centre.map((c) => c + reach) };
}

/** `p` clamped into the box. */
export function clampTo(/** @type {number[]} */ p, /** @type {{min: number[], max: number[]}} */ box) {
  return p.map((x, k) => Math.min(box.max[k], Math.max(box.min[k], x)));
}

/**
 * The nearest of `points` (screen positions) to (x, y) within `reach` CSS px, or -1.
 * @param {Array<{x: number, y: number, visible: boolean}>} points
 * @param {number} x @param {number} y @param {number} reach
 */
export function nearest(points, x, y, reach) {
  let best = -1,
    bestDistance = reach;
  points.forEach((p, i) => {
    if (!p.visible) return;
    const d = Math.hypot(p.x - x, p.y - y);
    if (d <= bestDistance) [best, bestDistance] = [i, d];
  });
  return best;
}
