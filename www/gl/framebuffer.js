// The multisampled framebuffer a frame is drawn into, resolved onto the canvas (whose own buffer
// is single-sampled: the context is made with antialias off). The same work the browser does for
// an antialiased canvas, in the page's hands: a frame can be drawn here, waited for off the main
// thread (gl/fence.js), and put on the canvas later by the resolve alone (viewer.js's first frame).
import { least } from '../reduce.js';

/** Pixels from which a framebuffer made is checked (2²² ≈ 2048 × 2048). */
const LARGE = 1 << 22;

export class Framebuffer {
  /** @param {WebGL2RenderingContext} gl */
  constructor(gl) {
    /** @internal */
    this.gl = gl;
    this.width = 0;
    this.height = 0;
    /** @internal @type {{framebuffer: WebGLFramebuffer | null, color: WebGLRenderbuffer | null, depth: WebGLRenderbuffer | null} | null} */
    this.buffers = null;
    /** @internal The size the GPU could not make a framebuffer of (not tried again until it changes). */
    this.refused = '';
  }

  /**
   * Binds the framebuffer for drawing, made or remade at `width` × `height` device pixels;
   * false (and the canvas bound) where the GPU cannot make one of that size (a large export).
   */
  bind(/** @type {number} */ width, /** @type {number} */ height) {
    const { gl } = this;
    if (!this.buffers || width !== this.width || height !== this.height) {
      this.dispose();
      const size = `${width} ${height}`;
      const largest = least(
        gl.getParameter(gl.MAX_VIEWPORT_DIMS) ?? [0],
        gl.getParameter(gl.MAX_RENDERBUFFER_SIZE) || 0,
      );
      if (this.refused === size || width > largest || height > largest || !this.make(width, height)) {
        this.refused = size;
        gl.bindFramebuffer(gl.FRAMEBUFFER, null);
        return false;
      }
      this.refused = '';
    }
    gl.bindFramebuffer(gl.FRAMEBUFFER, /** @type {NonNullable<Framebuffer['buffers']>} */ (this.buffers).framebuffer);
    return true;
  }

  /**
   * @internal Makes the framebuffer: multisampled (4 samples, or what the GPU allows), else
   * single-sampled where the GPU refuses that; whether one could be made.
   */
  make(/** @type {number} */ width, /** @type {number} */ height) {
    const { gl } = this;
    // the canvas's format (a resolve copies between buffers of one format; the context is asked
    // for no alpha, and read again here: after a context loss it may have been unknown)
    const format = (gl.getContextAttributes()?.alpha ?? false) ? gl.RGBA8 : gl.RGB8;
    for (const samples of [Math.min(4, gl.getParameter(gl.MAX_SAMPLES) || 0), 0]) {
      const framebuffer = gl.createFramebuffer();
      const color = gl.createRenderbuffer();
      const depth = gl.createRenderbuffer();
      gl.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
      for (const [buffer, inner, attachment] of [
        [color, format, gl.COLOR_ATTACHMENT0],
        [depth, gl.DEPTH_COMPONENT24, gl.DEPTH_ATTACHMENT],
      ]) {
        gl.bindRenderbuffer(gl.RENDERBUFFER, buffer);
        gl.renderbufferStorageMultisample(gl.RENDERBUFFER, samples, /** @type {number} */ (inner), width, height);
        gl.framebufferRenderbuffer(gl.FRAMEBUFFER, /** @type {number} */ (attachment), gl.RENDERBUFFER, buffer);
      }
      gl.bindRenderbuffer(gl.RENDERBUFFER, null);
      this.buffers = { framebuffer, color, depth };
      [this.width, this.height] = [width, height];
      // these formats are complete at any sample count up to MAX_SAMPLES (WebGL 2); only a large
      // framebuffer (an export at 4×) may fail for want of memory, and only there is it asked,
      // the answer waiting for the GPU
      if (width * height <= LARGE || gl.isContextLost()) return true;
      if (gl.checkFramebufferStatus(gl.FRAMEBUFFER) === gl.FRAMEBUFFER_COMPLETE) return true;
      this.dispose();
      if (samples === 0) break;
    }
    return false;
  }

  /** Resolves what was drawn onto the canvas (its default framebuffer, of the same size). */
  resolve() {
    const { gl, buffers, width, height } = this;
    if (!buffers) return;
    gl.bindFramebuffer(gl.READ_FRAMEBUFFER, buffers.framebuffer);
    gl.bindFramebuffer(gl.DRAW_FRAMEBUFFER, null);
    gl.blitFramebuffer(0, 0, width, height, 0, 0, width, height, gl.COLOR_BUFFER_BIT, gl.NEAREST);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
  }

  /** Frees the framebuffer (a later bind makes it again). */
  dispose() {
    const { gl, buffers } = this;
    if (!buffers) return;
    gl.deleteFramebuffer(buffers.framebuffer);
    gl.deleteRenderbuffer(buffers.color);
    gl.deleteRenderbuffer(buffers.depth);
    this.buffers = null;
    this.width = this.height = 0;
  }

  /** Forgets the framebuffer without freeing it: after a context loss every GL object is gone. */
  forget() {
    this.buffers = null;
  }
}
