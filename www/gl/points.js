// Points as round, lightly shaded sprites. Input: Float32Array, 3 floats per point.
import { cachedProgram } from './program.js';
import { createBuffer, floatAttribute } from './buffers.js';

const VS = `#version 300 es
layout(location = 0) in vec3 position;
uniform mat4 viewProj;
uniform float size;
void main() {
  gl_Position = viewProj * vec4(position, 1.0);
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

/** A batch of sprites with one colour and size. */
export class PointBatch {
  /**
   * @param {WebGL2RenderingContext} gl
   * @param {Float32Array} points 3 floats per point
   * @param {{color: number[], size: number}} style size in CSS pixels
   */
  constructor(gl, points, style) {
    this.count = points.length / 3;
    this.style = style;
    this.program = cachedProgram(gl, 'points', VS, FS, ['viewProj', 'size', 'color']);
    this.vao = gl.createVertexArray();
    gl.bindVertexArray(this.vao);
    this.buffer = createBuffer(gl, points);
    floatAttribute(gl, 0, this.buffer, 3);
    gl.bindVertexArray(null);
  }

  draw(gl, frame) {
    if (this.count === 0) return;
    const { program, u } = this.program;
    gl.useProgram(program);
    gl.uniformMatrix4fv(u.viewProj, false, frame.viewProj);
    gl.uniform1f(u.size, this.style.size * frame.dpr);
    gl.uniform4fv(u.color, this.style.color);
    gl.bindVertexArray(this.vao);
    gl.drawArrays(gl.POINTS, 0, this.count);
    gl.bindVertexArray(null);
  }

  dispose(gl) {
    gl.deleteBuffer(this.buffer);
    gl.deleteVertexArray(this.vao);
  }
}
