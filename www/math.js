// Small column-major 4×4 matrix and vector helpers (Float32Array, WebGL's layout).

/** @typedef {ArrayLike<number>} Vec3  three numbers */
/** @typedef {ArrayLike<number>} Mat4  sixteen numbers, column-major */

/**
 * @param {number} fovY vertical field of view, radians
 * @param {number} aspect width / height
 * @param {number} near
 * @param {number} far
 */
export function perspective(fovY, aspect, near, far) {
  const f = 1 / Math.tan(fovY / 2);
  const nf = 1 / (near - far);
  return new Float32Array([f / aspect, 0, 0, 0, 0, f, 0, 0, 0, 0, (far + near) * nf, -1, 0, 0, 2 * far * near * nf, 0]);
}

/** @param {Vec3} eye @param {Vec3} target @param {Vec3} up */
export function lookAt(eye, target, up) {
  const z = normalize(sub(eye, target));
  const x = normalize(cross(up, z));
  const y = cross(z, x);
  return new Float32Array([
    x[0],
    y[0],
    z[0],
    0,
    x[1],
    y[1],
    z[1],
    0,
    x[2],
    y[2],
    z[2],
    0,
    -dot(x, eye),
    -dot(y, eye),
    -dot(z, eye),
    1,
  ]);
}

/** a · b @param {Mat4} a @param {Mat4} b */
export function multiply(a, b) {
  const out = new Float32Array(16);
  for (let c = 0; c < 4; c++) {
    for (let r = 0; r < 4; r++) {
      let s = 0;
      for (let k = 0; k < 4; k++) s += a[k * 4 + r] * b[c * 4 + k];
      out[c * 4 + r] = s;
    }
  }
  return out;
}

export const sub = (/** @type {Vec3} */ a, /** @type {Vec3} */ b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
export const add = (/** @type {Vec3} */ a, /** @type {Vec3} */ b) => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
export const scale = (/** @type {Vec3} */ a, /** @type {number} */ s) => [a[0] * s, a[1] * s, a[2] * s];
export const dot = (/** @type {Vec3} */ a, /** @type {Vec3} */ b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
export const cross = (/** @type {Vec3} */ a, /** @type {Vec3} */ b) => [
  a[1] * b[2] - a[2] * b[1],
  a[2] * b[0] - a[0] * b[2],
  a[0] * b[1] - a[1] * b[0],
];
export const length = (/** @type {Vec3} */ a) => Math.hypot(a[0], a[1], a[2]);
export const normalize = (/** @type {Vec3} */ a) => scale(a, 1 / (length(a) || 1));

/**
 * Bounding box {min, max} of flat xyz data (NaN entries skipped).
 * @param {...ArrayLike<number>} arrays
 */
export function bounds(...arrays) {
  const min = [Infinity, Infinity, Infinity];
  const max = [-Infinity, -Infinity, -Infinity];
  for (const data of arrays) {
    for (let i = 0; i + 2 < data.length; i += 3) {
      for (let k = 0; k < 3; k++) {
        const v = data[i + k];
        if (v < min[k]) min[k] = v;
        if (v > max[k]) max[k] = v;
      }
    }
  }
  return { min, max };
}
