// Shaded triangle meshes with a front and a back colour: ruled strips (the quads
// a_i b_i b_{i+1} a_{i+1}, whose vertex buffer is the segment array itself: a_i at vertex 2i,
// b_i at 2i + 1), grids (director surfaces), and the core's meshes. Facet normals come from
// screen-space derivatives, so the facets of a discrete model show honestly; a mesh whose
// facets are smaller than a pixel brings vertex normals from the core instead (no moiré).
import { cachedProgram, beginDraw, prepareProgram } from './program.js';
import { createBuffer, floatAttribute, updateBuffer, IDENTITY } from './buffers.js';

const VS = `#version 300 es
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
uniform mat4 viewProj;
uniform mat4 model;
out vec3 world;
out vec3 smoothNormal;
void main() {
  vec4 p = model * vec4(position, 1.0);
  world = p.xyz;
  smoothNormal = mat3(model) * normal;
  gl_Position = viewProj * p;
}`;

const FS = `#version 300 es
precision highp float;
uniform vec3 eye;
uniform vec4 front;
uniform vec4 back;
uniform bool smoothShading;
in vec3 world;
in vec3 smoothNormal;
out vec4 outColor;
void main() {
  vec3 n = smoothShading && dot(smoothNormal, smoothNormal) > 0.0 ? normalize(smoothNormal) : normalize(cross(dFdx(world), dFdy(world)));
  vec3 v = normalize(eye - world);
  if (dot(n, v) < 0.0) n = -n;
  vec3 l = normalize(v + vec3(0.3, 0.2, 0.6));
  float diffuse = max(dot(n, l), 0.0);
  float spec = pow(max(dot(n, normalize(l + v)), 0.0), 40.0);
  vec4 base = gl_FrontFacing ? front : back;
  outColor = vec4(base.rgb * (0.45 + 0.55 * diffuse) + 0.2 * spec, base.a);
}`;

/** Starts compiling this kind's shaders (Viewer: before the first scene arrives). */
export function prepare(/** @type {WebGL2RenderingContext} */ gl) {
  prepareProgram(gl, 'mesh', VS, FS);
}

/** An indexed triangle mesh with one front and one back colour. */
export class TriangleMesh {
  /**
   * @param {WebGL2RenderingContext} gl
   * @param {Float32Array} positions 3 floats per vertex
   * @param {Uint32Array} indices 3 per triangle
   * @param {{front: number[], back: number[]}} style
   * @param {ArrayLike<number>} [transform]
   * @param {Float32Array} [normals] 3 floats per vertex: smooth shading
   */
  constructor(gl, positions, indices, style, transform = IDENTITY, normals = undefined) {
    this.style = style;
    this.transparent = style.front[3] < 1;
    this.count = indices.length;
    this.model = new Float32Array(transform);
    this.program = cachedProgram(gl, 'mesh', VS, FS, ['viewProj', 'model', 'eye', 'front', 'back', 'smoothShading']);
    this.smooth = !!normals;
    this.vao = gl.createVertexArray();
    gl.bindVertexArray(this.vao);
    this.vbo = createBuffer(gl, positions);
    floatAttribute(gl, 0, this.vbo, 3);
    this.nbo = normals ? createBuffer(gl, normals) : null;
    if (this.nbo) floatAttribute(gl, 1, this.nbo, 3);
    this.ibo = createBuffer(gl, indices, gl.ELEMENT_ARRAY_BUFFER);
    gl.bindVertexArray(null);
    /** @type {[Float32Array, Uint32Array, Float32Array | null]} what the buffers hold */
    this.data = [positions, indices, normals ?? null];
  }

  /**
   * New positions, indices (and normals) for the same style, uploaded only where they changed;
   * false where a mesh with normals and one without would share a batch (it is made anew).
   * @param {WebGL2RenderingContext} gl @param {Float32Array} positions @param {Uint32Array} indices
   * @param {ArrayLike<number>} [transform] @param {Float32Array} [normals]
   */
  update(gl, positions, indices, transform = IDENTITY, normals = undefined) {
    if (!!normals !== this.smooth) return false;
    gl.bindVertexArray(this.vao);
    const [p, i, n] = this.data;
    this.data = [
      updateBuffer(gl, this.vbo, positions, p),
      updateBuffer(gl, this.ibo, indices, i, gl.ELEMENT_ARRAY_BUFFER),
      normals && this.nbo ? updateBuffer(gl, this.nbo, normals, n) : null,
    ];
    gl.bindVertexArray(null);
    this.count = indices.length;
    this.model = new Float32Array(transform);
    return true;
  }

  /** @param {WebGL2RenderingContext} gl @param {import('../viewer.js').Frame} frame */
  draw(gl, frame) {
    if (this.count === 0) return;
    const u = beginDraw(gl, this.program, frame, this.model);
    gl.uniform3fv(u.eye, frame.eye);
    gl.uniform4fv(u.front, this.style.front);
    gl.uniform4fv(u.back, this.style.back);
    gl.uniform1i(u.smoothShading, this.smooth ? 1 : 0);
    gl.bindVertexArray(this.vao);
    gl.drawElements(gl.TRIANGLES, this.count, gl.UNSIGNED_INT, 0);
    gl.bindVertexArray(null);
  }

  /** @param {WebGL2RenderingContext} gl */
  dispose(gl) {
    gl.deleteBuffer(this.vbo);
    if (this.nbo) gl.deleteBuffer(this.nbo);
    gl.deleteBuffer(this.ibo);
    gl.deleteVertexArray(this.vao);
  }
}
