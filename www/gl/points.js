// Points as round, lightly shaded sprites (3 floats per point; NaN points are left out).
import { cachedProgram, beginDraw, prepareProgram } from './program.js';
import { createBuffer, floatAttribute, updateBuffer, IDENTITY } from './buffers.js';

const VS = `#version 300 es
layout(location = 0) in vec3 position;
uniform mat4 viewProj;
uniform mat4 model;
uniform float size;
void main() {
  gl_Position = viewProj * model * vec4(position, 1.0);
  gl_Position.z -= 4e-4 * gl_Position.w;
  gl_PointSize = size;
}`;

const FS = `#version 300 es
precision highp float;
uniform vec4 color;
out vec4 outColor;
void main() {
  vec2 p = gl_PointCoord * 2.0 - 1.0;
  float r2 = dot(p, p);
  if (r2 > 1.0) discard;
  float shade = 0.65 + 0.35 * sqrt(1.0 - r2) - 0.25 * p.y;
  float edge = 1.0 - smoothstep(0.8, 1.0, r2);
  outColor = vec4(color.rgb * shade, color.a * edge);
}`;

/** Points (3 floats each) without those holding NaN; the same array when all are finite. */
export function finitePoints(/** @type {Float32Array} */ data) {
  let all = true;
  for (let i = 0; i < data.length && all; i++) all = Number.isFinite(data[i]);
  if (all) return data;
  const out = new Float32Array(data.length);
  let k = 0;
  for (let i = 0; i + 2 < data.length; i += 3) {
    if (Number.isFinite(data[i]) && Number.isFinite(data[i + 1]) && Number.isFinite(data[i + 2]))
      out.set(data.subarray(i, i + 3), k++ * 3);
  }
  return out.subarray(0, 3 * k);
}

/** Starts compiling this kind's shaders (Viewer: before the first scene arrives). */
export function prepare(/** @type {WebGL2RenderingContext} */ gl) {
  prepareProgram(gl, 'points', VS, FS);
}

/** A batch of sprites with one colour and size. */
export class PointBatch {
  /**
   * @param {WebGL2RenderingContext} gl
   * @param {Float32Array} points 3 floats per point
   * @param {{color: number[], size: number}} style size in CSS pixels
   * @param {ArrayLike<number>} [transform]
   */
  constructor(gl, points, style, transform = IDENTITY) {
    const data = finitePoints(points);
    this.count = data.length / 3;
    this.style = style;
    this.model = new Float32Array(transform);
    this.program = cachedProgram(gl, 'points', VS, FS, ['viewProj', 'model', 'size', 'color']);
    this.vao = gl.createVertexArray();
    gl.bindVertexArray(this.vao);
    this.buffer = createBuffer(gl, data);
    floatAttribute(gl, 0, this.buffer, 3);
    gl.bindVertexArray(null);
    this.data = data;
  }

  /** New points for the same style: uploaded only where they changed (see updateBuffer). */
  update(
    /** @type {WebGL2RenderingContext} */ gl,
    /** @type {Float32Array} */ points,
    /** @type {ArrayLike<number>} */ transform = IDENTITY,
  ) {
    const data = finitePoints(points);
    this.data = updateBuffer(gl, this.buffer, data, this.data);
    this.count = data.length / 3;
    this.model = new Float32Array(transform);
  }

  /** @param {WebGL2RenderingContext} gl @param {import('../viewer.js').Frame} frame */
  draw(gl, frame) {
    if (this.count === 0) return;
    const u = beginDraw(gl, this.program, frame, this.model);
    gl.uniform1f(u.size, this.style.size * frame.dpr);
    gl.uniform4fv(u.color, this.style.color);
    gl.bindVertexArray(this.vao);
    gl.drawArrays(gl.POINTS, 0, this.count);
    gl.bindVertexArray(null);
  }

  /** @param {WebGL2RenderingContext} gl */
  dispose(gl) {
    gl.deleteBuffer(this.buffer);
    gl.deleteVertexArray(this.vao);
  }
}
