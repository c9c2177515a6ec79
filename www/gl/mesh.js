// Shaded triangle meshes: a discrete ruled surface as a strip (the quads a_i b_i b_{i+1}
// a_{i+1}; the vertex buffer is the segment array itself, a_i at vertex 2i, b_i at 2i + 1)
// and a grid of points as a surface (a director surface of a congruence). Facet normals come
// from screen-space derivatives, so the facets of a discrete model show honestly; front and
// back faces get different colours.
import { cachedProgram } from './program.js';
import { createBuffer, floatAttribute } from './buffers.js';

const VS = `#version 300 es
layout(location = 0) in vec3 position;
uniform mat4 viewProj;
out vec3 world;
void main() {
  world = position;
  gl_Position = viewProj * vec4(position, 1.0);
}`;

const FS = `#version 300 es
precision highp float;
uniform vec3 eye;
uniform vec4 front;
uniform vec4 back;
in vec3 world;
out vec4 outColor;
void main() {
  vec3 n = normalize(cross(dFdx(world), dFdy(world)));
  vec3 v = normalize(eye - world);
  if (dot(n, v) < 0.0) n = -n;
  vec3 l = normalize(v + vec3(0.3, 0.2, 0.6));
  float diffuse = max(dot(n, l), 0.0);
  float spec = pow(max(dot(n, normalize(l + v)), 0.0), 40.0);
  vec4 base = gl_FrontFacing ? front : back;
  outColor = vec4(base.rgb * (0.35 + 0.65 * diffuse) + 0.25 * spec, base.a);
}`;

/** Triangle indices of the strip between consecutive rulings (closed: wraps around). */
export function stripIndices(rulings, closed = false) {
  const quads = closed ? rulings : rulings - 1;
  const idx = new Uint32Array(6 * Math.max(quads, 0));
  for (let i = 0; i < quads; i++) {
    const a0 = 2 * i, b0 = a0 + 1;
    const a1 = (2 * (i + 1)) % (2 * rulings), b1 = a1 + 1;
    idx.set([a0, b0, b1, a0, b1, a1], 6 * i);
  }
  return idx;
}

/** Triangle indices of a rows × cols grid of points (row-major), two triangles per quad. */
export function gridIndices(rows, cols) {
  const idx = new Uint32Array(6 * (rows - 1) * (cols - 1));
  let m = 0;
  for (let i = 0; i + 1 < rows; i++) {
    for (let j = 0; j + 1 < cols; j++) {
      const a = i * cols + j, b = a + 1, c = a + cols, d = c + 1;
      idx.set([a, c, d, a, d, b], m);
      m += 6;
    }
  }
  return idx;
}

/** An indexed triangle mesh with one front and one back colour. */
export class TriangleMesh {
  /**
   * @param {WebGL2RenderingContext} gl
   * @param {Float32Array} positions 3 floats per vertex
   * @param {Uint32Array} indices 3 per triangle
   * @param {{front: number[], back: number[]}} style
   */
  constructor(gl, positions, indices, style) {
    this.style = style;
    this.transparent = style.front[3] < 1;
    this.count = indices.length;
    this.program = cachedProgram(gl, 'strip', VS, FS, ['viewProj', 'eye', 'front', 'back']);
    this.vao = gl.createVertexArray();
    gl.bindVertexArray(this.vao);
    this.vbo = createBuffer(gl, positions);
    floatAttribute(gl, 0, this.vbo, 3);
    this.ibo = createBuffer(gl, indices, gl.ELEMENT_ARRAY_BUFFER);
    gl.bindVertexArray(null);
  }

  draw(gl, frame) {
    if (this.count === 0) return;
    const { program, u } = this.program;
    gl.useProgram(program);
    gl.uniformMatrix4fv(u.viewProj, false, frame.viewProj);
    gl.uniform3fv(u.eye, frame.eye);
    gl.uniform4fv(u.front, this.style.front);
    gl.uniform4fv(u.back, this.style.back);
    gl.bindVertexArray(this.vao);
    gl.drawElements(gl.TRIANGLES, this.count, gl.UNSIGNED_INT, 0);
    gl.bindVertexArray(null);
  }

  dispose(gl) {
    gl.deleteBuffer(this.vbo);
    gl.deleteBuffer(this.ibo);
    gl.deleteVertexArray(this.vao);
  }
}

/** A ruled strip from its segments (6 floats per ruling). */
export function stripMesh(gl, segments, style) {
  return new TriangleMesh(gl, segments, stripIndices(segments.length / 6, style.closed), style);
}
