// Shader programs: compile, link, and report errors with the offending source lines.

/**
 * Compiles and links a WebGL2 program. On a compile error the thrown Error quotes the
 * driver's log and the numbered source lines it points at.
 * @param {WebGL2RenderingContext} gl
 * @param {string} vertexSource
 * @param {string} fragmentSource
 * @returns {WebGLProgram}
 */
export function createProgram(gl, vertexSource, fragmentSource) {
  const program = /** @type {WebGLProgram} */ (gl.createProgram());
  gl.attachShader(program, compileShader(gl, gl.VERTEX_SHADER, vertexSource));
  gl.attachShader(program, compileShader(gl, gl.FRAGMENT_SHADER, fragmentSource));
  gl.linkProgram(program);
  if (!gl.getProgramParameter(program, gl.LINK_STATUS) && !gl.isContextLost()) {
    throw new Error(`shader link failed: ${gl.getProgramInfoLog(program)}`);
  }
  return program;
}

/**
 * @param {WebGL2RenderingContext} gl
 * @param {number} type gl.VERTEX_SHADER or gl.FRAGMENT_SHADER
 * @param {string} source
 */
export function compileShader(gl, type, source) {
  // null only when the context is lost; then every call below is a no-op (WebGL's rule)
  const shader = /** @type {WebGLShader} */ (gl.createShader(type));
  gl.shaderSource(shader, source);
  gl.compileShader(shader);
  if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS) && !gl.isContextLost()) {
    const log = gl.getShaderInfoLog(shader) ?? '';
    const kind = type === gl.VERTEX_SHADER ? 'vertex' : 'fragment';
    throw new Error(`${kind} shader compile failed:\n${log}\n${numberedLines(source, log)}`);
  }
  return shader;
}

/**
 * The source with line numbers, the lines named in an "ERROR: 0:LINE:" log marked.
 * @param {string} source
 */
export function numberedLines(source, log = '') {
  const bad = new Set([...log.matchAll(/ERROR: \d+:(\d+)/g)].map((m) => Number(m[1])));
  return source
    .split('\n')
    .map((line, i) => `${bad.has(i + 1) ? '>>' : '  '}${String(i + 1).padStart(4)}: ${line}`)
    .join('\n');
}

/**
 * Uniform locations of a program by name.
 * @param {WebGL2RenderingContext} gl
 * @param {WebGLProgram} program
 * @param {string[]} names
 * @returns {Record<string, WebGLUniformLocation | null>}
 */
export function uniforms(gl, program, names) {
  return Object.fromEntries(names.map((n) => [n, gl.getUniformLocation(program, n)]));
}

/**
 * A context's programs by key: checked (their uniforms looked up) once first used, or still
 * compiling (prepareProgram).
 * @typedef {{program: WebGLProgram, u: Record<string, WebGLUniformLocation | null>}} Cached
 * @typedef {{compiling: {program: WebGLProgram, vertexSource: string, fragmentSource: string}}} Compiling
 * @type {WeakMap<WebGL2RenderingContext, Map<string, Cached | Compiling>>}
 */
const cache = new WeakMap();

/** The programs of `gl`. */
function programsOf(/** @type {WebGL2RenderingContext} */ gl) {
  let programs = cache.get(gl);
  if (!programs) {
    programs = new Map();
    cache.set(gl, programs);
  }
  return programs;
}

/**
 * Starts compiling and linking a program without waiting for the result: the GPU compiles
 * while the page goes on (the core loading, the first scene computing), and the first
 * cachedProgram of the key checks it, with the same error messages as createProgram.
 * @param {WebGL2RenderingContext} gl
 * @param {string} key
 * @param {string} vertexSource
 * @param {string} fragmentSource
 */
export function prepareProgram(gl, key, vertexSource, fragmentSource) {
  const programs = programsOf(gl);
  if (programs.has(key)) return;
  const program = /** @type {WebGLProgram} */ (gl.createProgram());
  for (const [type, source] of [
    [gl.VERTEX_SHADER, vertexSource],
    [gl.FRAGMENT_SHADER, fragmentSource],
  ]) {
    const shader = /** @type {WebGLShader} */ (gl.createShader(/** @type {number} */ (type)));
    gl.shaderSource(shader, /** @type {string} */ (source));
    gl.compileShader(shader);
    gl.attachShader(program, shader);
  }
  gl.linkProgram(program);
  programs.set(key, { compiling: { program, vertexSource, fragmentSource } });
}

/**
 * A program compiled once per context and shared by every batch that draws with it.
 * @param {WebGL2RenderingContext} gl
 * @param {string} key a name for the shader pair
 * @param {string} vertexSource
 * @param {string} fragmentSource
 * @param {string[]} uniformNames
 * @returns {{program: WebGLProgram, u: Record<string, WebGLUniformLocation | null>}}
 */
export function cachedProgram(gl, key, vertexSource, fragmentSource, uniformNames) {
  const programs = programsOf(gl);
  const entry = programs.get(key);
  if (entry && 'program' in entry) return entry;
  let program;
  if (entry && !gl.getProgramParameter(entry.compiling.program, gl.LINK_STATUS) && !gl.isContextLost()) {
    // compiled again, for createProgram's message (which shader failed, its lines)
    createProgram(gl, entry.compiling.vertexSource, entry.compiling.fragmentSource);
    throw new Error(`shader link failed: ${gl.getProgramInfoLog(entry.compiling.program)}`);
  } else program = entry ? entry.compiling.program : createProgram(gl, vertexSource, fragmentSource);
  const cached = { program, u: uniforms(gl, program, uniformNames) };
  programs.set(key, cached);
  return cached;
}

/**
 * Forgets every cached program of `gl`: after a context loss all GL objects are invalid.
 * @param {WebGL2RenderingContext} gl
 */
export function forgetPrograms(gl) {
  cache.delete(gl);
}

/**
 * Starts a draw with a cached program: binds it and sets the uniforms every batch has, the
 * frame's view-projection and the batch's model matrix; returns the uniform locations.
 * @param {WebGL2RenderingContext} gl
 * @param {{ program: WebGLProgram, u: Record<string, WebGLUniformLocation | null> }} cached
 * @param {import('../viewer.js').Frame} frame
 * @param {Float32Array} model
 */
export function beginDraw(gl, { program, u }, frame, model) {
  gl.useProgram(program);
  gl.uniformMatrix4fv(u.viewProj, false, frame.viewProj);
  gl.uniformMatrix4fv(u.model, false, model);
  return u;
}
