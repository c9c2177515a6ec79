// Where a handle is on screen and the ray back through a pixel: the camera's projection of a
// handle, the ray through a pointer, the rigid motions a set is drawn with, and the box handles
// stay in. This is the camera's geometry (the page's), not the paper's: where a drag puts a
// handle — on a plane, a line, snapped — the core decides (edit/snap.js, snapPoint).
import { add, cross, normalize, scale, sub } from '../math.js';
import { greatest } from '../reduce.js';

/** @typedef {[number, number, number]} Vec3 */
/** @typedef {{origin: number[], dir: number[]}} Ray */
/**
 * How a drag moves a handle: in the plane through it facing the viewer, along its own line (a
 * ruling, a tool axis), or along the input's z-axis.
 * @typedef {'view' | 'line' | 'vertical'} MoveMode
 */

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
 * The inverse of a similarity x ↦ s R x + t (a rigid motion scaled by s > 0, as a set is drawn:
 * the bending scene's turned surface, the Klein scene's lines beside M) given as a 4 × 4
 * column-major matrix: (s R)⁻¹ = (s R)ᵀ / s², s² the squared length of its first column, and the
 * translation taken back.
 * @param {ArrayLike<number>} m
 * @returns {Float64Array}
 */
export function invertSimilarity(m) {
  const s2 = m[0] * m[0] + m[1] * m[1] + m[2] * m[2];
  const r = new Float64Array(16);
  for (let i = 0; i < 3; i++) for (let j = 0; j < 3; j++) r[4 * j + i] = m[4 * i + j] / s2;
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
 * The box handles stay in: the scene's bounds scaled by `factor` about their centre (a cube
 * when the scene is flat in some direction).
 * @param {{min: number[], max: number[]}} bounds
 * @param {number} factor
 */
export function editBox({ min, max }, factor) {
  const centre = min.map((a, k) => (a + max[k]) / 2);
  const half = greatest(
    min.map((a, k) => (max[k] - a) / 2),
    1e-6,
  );
  const reach = factor * half;
  return { min: centre.map((c) => c - reach), max: centre.map((c) => c + reach) };
}

/** `p` clamped into the box. */
export function clampTo(/** @type {number[]} */ p, /** @type {{min: number[], max: number[]}} */ box) {
  return p.map((x, k) => Math.min(box.max[k], Math.max(box.min[k], x)));
}
