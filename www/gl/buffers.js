// Buffers and vertex arrays.

/** The 4 × 4 identity, column-major. */
export const IDENTITY = Object.freeze([1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]);

/**
 * Uploads typed-array data into a new buffer.
 * @param {WebGL2RenderingContext} gl
 * @param {ArrayBufferView} data
 * @param {number} [target] gl.ARRAY_BUFFER (default) or gl.ELEMENT_ARRAY_BUFFER
 */
export function createBuffer(gl, data, target = gl.ARRAY_BUFFER) {
  const buffer = gl.createBuffer();
  gl.bindBuffer(target, buffer);
  gl.bufferData(target, data, gl.STATIC_DRAW);
  return buffer;
}

/**
 * Puts `data` into `buffer` (bound to `target`): nothing when it holds these numbers already (the
 * `last` it was given), in place when the size is the same, else anew. Returns `data` (the next
 * `last`). A drag changes one handle: most layers come back equal and go to the GPU no more.
 * @template {ArrayBufferView & ArrayLike<number>} T
 * @param {WebGL2RenderingContext} gl
 * @param {WebGLBuffer | null} buffer
 * @param {T} data
 * @param {T | null} last
 * @param {number} [target]
 * @returns {T}
 */
export function updateBuffer(gl, buffer, data, last, target = gl.ARRAY_BUFFER) {
  if (last && last.length === data.length) {
    let same = true;
    for (let i = 0; i < data.length && same; i++) same = Object.is(data[i], last[i]);
    if (same) return data;
  }
  gl.bindBuffer(target, buffer);
  if (last && last.length === data.length) gl.bufferSubData(target, 0, data);
  else gl.bufferData(target, data, gl.STATIC_DRAW);
  return data;
}

/**
 * Binds a float attribute of `size` components to `buffer` (bound VAO assumed).
 * @param {WebGL2RenderingContext} gl
 * @param {number} location
 * @param {WebGLBuffer | null} buffer
 * @param {number} size
 * @param {{stride?: number, offset?: number, divisor?: number}} [layout]
 */
export function floatAttribute(gl, location, buffer, size, { stride = 0, offset = 0, divisor = 0 } = {}) {
  if (location < 0) return;
  gl.bindBuffer(gl.ARRAY_BUFFER, buffer);
  gl.enableVertexAttribArray(location);
  gl.vertexAttribPointer(location, size, gl.FLOAT, false, stride, offset);
  gl.vertexAttribDivisor(location, divisor);
}
