// The WebGL2 viewer: owns the canvas and context, sizes it for the device pixel ratio,
// renders on demand, and rebuilds a scene's GPU objects after a context loss.
import { OrbitCamera } from './camera.js';
import { forgetPrograms } from './gl/program.js';

/**
 * A scene supplies GPU layers and its bounds:
 *   { bounds: {min, max}, build(gl): Array<{draw(gl, frame), dispose(gl), transparent?: boolean}> }
 */
export class Viewer {
  /**
   * @param {HTMLCanvasElement} canvas
   * @param {{background?: number[]}} [options]
   */
  constructor(canvas, { background = [0.984, 0.98, 0.969, 1] } = {}) {
    this.canvas = canvas;
    this.background = background;
    this.camera = new OrbitCamera();
    this.layers = [];
    this.scene = null;
    this.frames = 0;
    this.pending = false;
    this.onFrame = null;
    // HTML labels anchored to 3D points (scene.labels: [{ at: [x, y, z], html }])
    this.labelLayer = document.createElement('div');
    this.labelLayer.className = 'labels';
    canvas.after(this.labelLayer);
    const gl = canvas.getContext('webgl2', { antialias: true, alpha: false, preserveDrawingBuffer: false });
    if (!gl) throw new Error('This page needs WebGL2, which this browser does not provide.');
    this.gl = gl;
    canvas.addEventListener('webglcontextlost', (e) => {
      e.preventDefault();
      this.lost = true;
      this.layers = [];
    });
    canvas.addEventListener('webglcontextrestored', () => {
      this.lost = false;
      forgetPrograms(gl);
      this.rebuild();
    });
    this.onCameraChange = null;
    this.camera.attach(canvas, () => {
      this.requestRender();
      this.onCameraChange?.();
    });
    new ResizeObserver(() => this.requestRender()).observe(canvas);
  }

  /** Shows `scene`; `fit` reframes the camera on its bounds. */
  setScene(scene, { fit = false } = {}) {
    this.scene = scene;
    if (fit) {
      // a scene may suggest the direction it is best seen from
      if (scene.camera) Object.assign(this.camera, scene.camera);
      this.camera.fit(scene.bounds);
    }
    this.rebuild();
  }

  rebuild() {
    this.labelLayer.replaceChildren(
      ...(this.scene?.labels ?? []).map(({ html }) => Object.assign(document.createElement('span'), { className: 'label', innerHTML: html })),
    );
    const gl = this.gl;
    this.layers.forEach((l) => l.dispose(gl));
    this.layers = this.scene && !this.lost ? this.scene.build(gl) : [];
    this.requestRender();
  }

  requestRender() {
    if (this.pending) return;
    this.pending = true;
    requestAnimationFrame(() => {
      this.pending = false;
      this.render();
    });
  }

  render() {
    const { gl, canvas } = this;
    if (this.lost || gl.isContextLost()) return;
    const dpr = window.devicePixelRatio || 1;
    const width = Math.max(1, Math.round(canvas.clientWidth * dpr));
    const height = Math.max(1, Math.round(canvas.clientHeight * dpr));
    if (canvas.width !== width || canvas.height !== height) {
      canvas.width = width;
      canvas.height = height;
    }
    gl.viewport(0, 0, width, height);
    gl.clearColor(...this.background);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    gl.enable(gl.DEPTH_TEST);
    gl.enable(gl.BLEND);
    gl.blendFunc(gl.SRC_ALPHA, gl.ONE_MINUS_SRC_ALPHA);
    const frame = { viewProj: this.camera.viewProj(width / height), eye: this.camera.eye, width, height, dpr };
    for (const transparent of [false, true]) {
      gl.depthMask(!transparent);
      for (const layer of this.layers) if (!!layer.transparent === transparent) layer.draw(gl, frame);
    }
    gl.depthMask(true);
    this.placeLabels(frame.viewProj);
    this.frames++;
    this.onFrame?.(this.frames);
  }

  /** Moves each label to the screen position of its anchor (hidden behind the camera). */
  placeLabels(viewProj) {
    const labels = this.scene?.labels ?? [];
    const { clientWidth: w, clientHeight: h } = this.canvas;
    labels.forEach(({ at }, k) => {
      const el = this.labelLayer.children[k];
      if (!el) return;
      const [x, y, z] = at;
      const cx = viewProj[0] * x + viewProj[4] * y + viewProj[8] * z + viewProj[12];
      const cy = viewProj[1] * x + viewProj[5] * y + viewProj[9] * z + viewProj[13];
      const cw = viewProj[3] * x + viewProj[7] * y + viewProj[11] * z + viewProj[15];
      el.hidden = cw <= 0;
      el.style.transform = `translate(${((cx / cw + 1) / 2) * w}px, ${((1 - cy / cw) / 2) * h}px)`;
    });
  }
}
