// Thick lines as instanced screen-space quads (gl.lineWidth is 1 in browsers), optionally
// dashed, optionally moved by a model matrix. A batch takes the core's f32 segments (6 floats
// per segment) or a polyline (3 per point); records holding NaN are left out when uploading.
import { cachedProgram, beginDraw, prepareProgram } from './program.js';
import { createBuffer, floatAttribute, updateBuffer, IDENTITY } from './buffers.js';

const VS = `#version 300 es
layout(location = 0) in vec2 corner;   // x: 0 at p0, 1 at p1; y: -1 or 1 across
layout(location = 1) in vec3 p0;
layout(location = 2) in vec3 p1;
uniform mat4 viewProj;
uniform mat4 model;
uniform vec2 viewport;                 // half the viewport, device pixels
uniform float width;                   // half the line width, device pixels
out float across;
out float along;                       // device pixels from p0
void main() {
  vec4 c0 = viewProj * model * vec4(p0, 1.0);
  vec4 c1 = viewProj * model * vec4(p1, 1.0);
  vec2 s0 = c0.xy / c0.w * viewport;
  vec2 s1 = c1.xy / c1.w * viewport;
  vec2 d = s1 - s0;
  float len = length(d);
  vec2 dir = len > 1e-6 ? d / len : vec2(1.0, 0.0);
  vec2 nrm = vec2(-dir.y, dir.x);
  vec4 c = mix(c0, c1, corner.x);
  float end = corner.x * 2.0 - 1.0;
  c.xy += (nrm * corner.y + dir * end) * width / viewport * c.w;
  c.z -= 2e-4 * c.w;                   // just in front of the surface the line lies on
  gl_Position = c;
  across = corner.y;
  along = corner.x * len + end * width;
}`;

const FS = `#version 300 es
precision highp float;
uniform vec4 color;
uniform vec4 dash;                     // on, off, on, off in device pixels (all 0: solid)
in float across;
in float along;
out vec4 outColor;
void main() {
  float period = dash.x + dash.y + dash.z + dash.w;
  if (period > 0.0) {
    float phase = mod(max(along, 0.0), period);
    if ((phase > dash.x && phase < dash.x + dash.y) || phase > dash.x + dash.y + dash.z) discard;
  }
  float a = 1.0 - smoothstep(0.6, 1.0, abs(across));
  outColor = vec4(color.rgb, color.a * a);
}`;

/**
 * Segments (6 floats each) without the ones holding NaN or ±∞; the same array when all are finite.
 * @param {Float32Array} data
 */
export function finiteSegments(data) {
  let all = true;
  for (let i = 0; i < data.length && all; i++) all = Number.isFinite(data[i]);
  if (all) return data;
  const out = new Float32Array(data.length);
  let k = 0;
  for (let i = 0; i + 5 < data.length; i += 6) {
    let ok = true;
    for (let j = 0; j < 6; j++) ok &&= Number.isFinite(data[i + j]);
    if (ok) out.set(data.subarray(i, i + 6), k++ * 6);
  }
  return out.subarray(0, 6 * k);
}

/**
 * The segments joining consecutive points of a polyline (3 floats per point), skipping any
 * that touch a NaN point; `closed` joins the last point to the first.
 * @param {Float32Array} points
 * @param {boolean} [closed]
 */
export function polylineSegments(points, closed = false) {
  const n = points.length / 3;
  const count = closed && n > 2 ? n : Math.max(n - 1, 0);
  const out = new Float32Array(6 * count);
  for (let i = 0; i < count; i++) {
    const j = (i + 1) % n;
    out.set(points.subarray(3 * i, 3 * i + 3), 6 * i);
    out.set(points.subarray(3 * j, 3 * j + 3), 6 * i + 3);
  }
  return finiteSegments(out);
}

/** Starts compiling this kind's shaders (Viewer: before the first scene arrives). */
export function prepare(/** @type {WebGL2RenderingContext} */ gl) {
  prepareProgram(gl, 'lines', VS, FS);
}

/** A batch of thick segments with one style. */
export class LineBatch {
  /**
   * @param {WebGL2RenderingContext} gl
   * @param {Float32Array} segments 6 floats per segment
   * @param {{color: number[], width: number, dash?: number[]}} style width and dash in CSS pixels
   * @param {ArrayLike<number>} [transform] model matrix, column-major
   */
  constructor(gl, segments, style, transform = IDENTITY) {
    const data = finiteSegments(segments);
    this.count = data.length / 6;
    this.style = style;
    this.model = new Float32Array(transform);
    this.program = cachedProgram(gl, 'lines', VS, FS, ['viewProj', 'model', 'viewport', 'width', 'color', 'dash']);
    this.vao = gl.createVertexArray();
    gl.bindVertexArray(this.vao);
    const corners = createBuffer(gl, new Float32Array([0, -1, 1, -1, 0, 1, 1, 1]));
    floatAttribute(gl, 0, corners, 2);
    const inst = createBuffer(gl, data);
    floatAttribute(gl, 1, inst, 3, { stride: 24, offset: 0, divisor: 1 });
    floatAttribute(gl, 2, inst, 3, { stride: 24, offset: 12, divisor: 1 });
    gl.bindVertexArray(null);
    this.buffers = [corners, inst];
    this.data = data;
    this.transparent = (style.color[3] ?? 1) < 1;
  }

  /** New segments for the same style: uploaded only where they changed (see updateBuffer). */
  update(
    /** @type {WebGL2RenderingContext} */ gl,
    /** @type {Float32Array} */ segments,
    /** @type {ArrayLike<number>} */ transform = IDENTITY,
  ) {
    const data = finiteSegments(segments);
    this.data = updateBuffer(gl, this.buffers[1], data, this.data);
    this.count = data.length / 6;
    this.model = new Float32Array(transform);
  }

  /** @param {WebGL2RenderingContext} gl @param {import('../viewer.js').Frame} frame */
  draw(gl, frame) {
    if (this.count === 0) return;
    const u = beginDraw(gl, this.program, frame, this.model);
    gl.uniform2f(u.viewport, frame.width / 2, frame.height / 2);
    gl.uniform1f(u.width, (this.style.width * frame.dpr) / 2);
    gl.uniform4fv(u.color, this.style.color);
    const dash = [0, 0, 0, 0];
    (this.style.dash ?? []).slice(0, 4).forEach((x, i) => {
      dash[i] = x * frame.dpr;
    });
    if (dash[2] === 0 && dash[3] === 0) [dash[2], dash[3]] = [dash[0], dash[1]];
    gl.uniform4fv(u.dash, dash);
    gl.bindVertexArray(this.vao);
    gl.drawArraysInstanced(gl.TRIANGLE_STRIP, 0, 4, this.count);
    gl.bindVertexArray(null);
  }

  /** @param {WebGL2RenderingContext} gl */
  dispose(gl) {
    this.buffers.forEach((b) => {
      gl.deleteBuffer(b);
    });
    gl.deleteVertexArray(this.vao);
  }
}
