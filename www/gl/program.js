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
  const program = gl.createProgram();
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
  const shader = gl.createShader(type);
  gl.shaderSource(shader, source);
  gl.compileShader(shader);
  if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS) && !gl.isContextLost()) {
    const log = gl.getShaderInfoLog(shader) ?? '';
    const kind = type === gl.VERTEX_SHADER ? 'vertex' : 'fragment';
    throw new Error(`${kind} shader compile failed:\n${log}\n${numberedLines(source, log)}`);
  }
  return shader;
}

/** The source with line numbers, the lines named in an "ERROR: 0:LINE:" log marked. */
export function numberedLines(source, log = '') {
  const bad = new Set([...log.matchAll(/ERROR: \d+:(\d+)/g)].map((m) => Number(m[1])));
  return source
    .split('\n')
    .map((line, i) => `${bad.has(i + 1) ? '>>' : '  '}${String(i + 1).padStart(4)}: ${line}`)
    .join('\n');
}

/** Uniform locations of a program by name. */
export function uniforms(gl, program, names) {
  return Object.fromEntries(names.map((n) => [n, gl.getUniformLocation(program, n)]));
}

const cache = new WeakMap();

/**
 * A program compiled once per context and shared by every batch that draws with it.
 * @param {WebGL2RenderingContext} gl
 * @param {string} key a name for the shader pair
 * @returns {{program: WebGLProgram, u: Object<string, WebGLUniformLocation>}}
 */
export function cachedProgram(gl, key, vertexSource, fragmentSource, uniformNames) {
  let programs = cache.get(gl);
  if (!programs) cache.set(gl, (programs = new Map()));
  if (!programs.has(key)) {
    const program = createProgram(gl, vertexSource, fragmentSource);
    programs.set(key, { program, u: uniforms(gl, program, uniformNames) });
  }
  return programs.get(key);
}

/** Forgets every cached program of `gl`: after a context loss all GL objects are invalid. */
export function forgetPrograms(gl) {
  cache.delete(gl);
}
