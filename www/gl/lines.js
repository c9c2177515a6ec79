// Thick lines as instanced screen-space quads (gl.lineWidth is 1 in browsers).
// Input is a flat Float32Array of segments, 6 floats each (x0 y0 z0 x1 y1 z1): exactly the
// layout of RuledSurface.segmentsF32() and of the footpoint arrays, so no per-line objects.
import { cachedProgram } from './program.js';
import { createBuffer, floatAttribute } from './buffers.js';

const VS = `#version 300 es
layout(location = 0) in vec2 corner;   // x: 0 at p0, 1 at p1; y: -1 or 1 across
layout(location = 1) in vec3 p0;
layout(location = 2) in vec3 p1;
uniform mat4 viewProj;
uniform vec2 viewport;                 // in device pixels
uniform float width;                   // in device pixels
out float across;
void main() {
  vec4 c0 = viewProj * vec4(p0, 1.0);
  vec4 c1 = viewProj * vec4(p1, 1.0);
  vec2 s0 = c0.xy / c0.w * viewport;
  vec2 s1 = c1.xy / c1.w * viewport;
  vec2 d = s1 - s0;
  float len = length(d);
  vec2 dir = len > 1e-6 ? d / len : vec2(1.0, 0.0);
  vec2 nrm = vec2(-dir.y, dir.x);
  vec4 c = mix(c0, c1, corner.x);
  vec2 offset = (nrm * corner.y + dir * (corner.x * 2.0 - 1.0)) * width;
  c.xy += offset / viewport * c.w;
  c.z -= 2e-4 * c.w;                   // draw lines just in front of the surface they lie on
  gl_Position = c;
  across = corner.y;
}`;

const FS = `#version 300 es
precision highp float;
uniform vec4 color;
in float across;
out vec4 outColor;
void main() {
  float a = 1.0 - smoothstep(0.6, 1.0, abs(across));
  outColor = vec4(color.rgb, color.a * a);
}`;

/** A batch of thick segments with one colour and width. */
export class LineBatch {
  /**
   * @param {WebGL2RenderingContext} gl
   * @param {Float32Array} segments 6 floats per segment
   * @param {{color: number[], width: number}} style width in CSS pixels
   */
  constructor(gl, segments, style) {
    this.count = segments.length / 6;
    this.style = style;
    this.program = cachedProgram(gl, 'lines', VS, FS, ['viewProj', 'viewport', 'width', 'color']);
    this.vao = gl.createVertexArray();
    gl.bindVertexArray(this.vao);
    const corners = createBuffer(gl, new Float32Array([0, -1, 1, -1, 0, 1, 1, 1]));
    floatAttribute(gl, 0, corners, 2);
    const inst = createBuffer(gl, segments);
    floatAttribute(gl, 1, inst, 3, { stride: 24, offset: 0, divisor: 1 });
    floatAttribute(gl, 2, inst, 3, { stride: 24, offset: 12, divisor: 1 });
    gl.bindVertexArray(null);
    this.buffers = [corners, inst];
  }

  /** @param {WebGL2RenderingContext} gl */
  draw(gl, frame) {
    if (this.count === 0) return;
    const { program, u } = this.program;
    gl.useProgram(program);
    gl.uniformMatrix4fv(u.viewProj, false, frame.viewProj);
    gl.uniform2f(u.viewport, frame.width / 2, frame.height / 2);
    gl.uniform1f(u.width, (this.style.width * frame.dpr) / 2);
    gl.uniform4fv(u.color, this.style.color);
    gl.bindVertexArray(this.vao);
    gl.drawArraysInstanced(gl.TRIANGLE_STRIP, 0, 4, this.count);
    gl.bindVertexArray(null);
  }

  /** @param {WebGL2RenderingContext} gl */
  dispose(gl) {
    this.buffers.forEach((b) => gl.deleteBuffer(b));
    gl.deleteVertexArray(this.vao);
  }
}
