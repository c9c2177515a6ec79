// The multisampled framebuffer a frame is drawn into, resolved onto the canvas (whose own buffer
// is single-sampled: the context is made with antialias off). The same work the browser does for
// an antialiased canvas, in the page's hands: a frame can be drawn here, waited for off the main
// thread (gl/fence.js), and put on the canvas later by the resolve alone (viewer.js's first frame).

export class FrameTarget {
  /** @param {WebGL2RenderingContext} gl */
  constructor(gl) {
    /** @internal */
    this.gl = gl;
    // (the canvas's format: a resolve copies between buffers of one format)
    const alpha = gl.getContextAttributes()?.alpha ?? true;
    /** @internal */
    this.format = alpha ? gl.RGBA8 : gl.RGB8;
    /** @internal Samples per pixel: 4, or what the GPU allows for the format. */
    this.samples = Math.min(4, gl.getParameter(gl.MAX_SAMPLES) || 0);
    this.width = 0;
    this.height = 0;
    /** @internal @type {{framebuffer: WebGLFramebuffer | null, color: WebGLRenderbuffer | null, depth: WebGLRenderbuffer | null} | null} */
    this.buffers = null;
  }

  /** Binds the framebuffer for drawing, made or remade at `width` × `height` device pixels. */
  bind(/** @type {number} */ width, /** @type {number} */ height) {
    const { gl } = this;
    if (!this.buffers || width !== this.width || height !== this.height) {
      this.dispose();
      const framebuffer = gl.createFramebuffer();
      const color = gl.createRenderbuffer();
      const depth = gl.createRenderbuffer();
      gl.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
      for (const [buffer, format, attachment] of [
        [color, this.format, gl.COLOR_ATTACHMENT0],
        [depth, gl.DEPTH_COMPONENT24, gl.DEPTH_ATTACHMENT],
      ]) {
        gl.bindRenderbuffer(gl.RENDERBUFFER, buffer);
        gl.renderbufferStorageMultisample(gl.RENDERBUFFER, this.samples, /** @type {number} */ (format), width, height);
        gl.framebufferRenderbuffer(gl.FRAMEBUFFER, /** @type {number} */ (attachment), gl.RENDERBUFFER, buffer);
      }
      gl.bindRenderbuffer(gl.RENDERBUFFER, null);
      this.buffers = { framebuffer, color, depth };
      [this.width, this.height] = [width, height];
    }
    gl.bindFramebuffer(gl.FRAMEBUFFER, this.buffers.framebuffer);
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
  }

  /** Forgets the framebuffer without freeing it: after a context loss every GL object is gone. */
  forget() {
    this.buffers = null;
  }
}
