// The WebGL2 viewer: owns a canvas and its context, sizes it for the device pixel ratio,
// turns a scene's layers (f32 buffers from the core, and styles of theme.js) into GPU
// batches, renders on demand, places the 3D-anchored labels, rebuilds after a context loss,
// and releases the context when disposed. Buffers go to the GPU in the animation frame that
// draws them (the computation and the upload are separate tasks; two computations in one frame
// upload once); a layer of the same kind and style as before keeps its batch, and only numbers
// that changed are uploaded again (a drag moves one handle: most layers come back equal).
import { OrbitCamera } from './camera.js';
import { forgetPrograms } from './gl/program.js';
import { LineBatch, polylineSegments, prepare as prepareLines } from './gl/lines.js';
import { PointBatch, prepare as preparePoints } from './gl/points.js';
import { TriangleMesh, prepare as prepareMeshes } from './gl/mesh.js';
import { STYLES, rgb, rgba, PALETTE } from './theme.js';
import { appendRich } from './ui/richtext.js';
import { mark, measured } from './timing.js';
import { Framebuffer } from './gl/framebuffer.js';
import { finished } from './gl/fence.js';
import { afterPaint } from './schedule.js';

/**
 * What a layer draws with in one frame.
 * @typedef {object} Frame
 * @property {Float32Array} viewProj
 * @property {number[]} eye
 * @property {number} width   device pixels
 * @property {number} height
 * @property {number} dpr
 */

/**
 * @typedef {{draw(gl: WebGL2RenderingContext, frame: Frame): void, dispose(gl: WebGL2RenderingContext): void, transparent?: boolean, layer?: string}} Batch
 */

/**
 * Puts `layer` into `old`, the batch of the layer before it, where that is of the same kind and
 * style (only what changed is uploaded); returns whether it did.
 * @param {WebGL2RenderingContext} gl
 * @param {Batch | null | undefined} old
 * @param {import('./scene.js').Layer} layer
 */
function reuse(gl, old, layer) {
  if (!old || old.layer !== `${layer.kind} ${layer.style}`) return false;
  const transform = layer.transform ?? undefined;
  if (old instanceof TriangleMesh)
    return old.update(gl, layer.positions, /** @type {Uint32Array} */ (layer.indices), transform, layer.normals);
  if (old instanceof PointBatch) old.update(gl, layer.positions, transform);
  else if (old instanceof LineBatch)
    old.update(
      gl,
      layer.kind === 'polyline' ? polylineSegments(layer.positions, layer.closed) : layer.positions,
      transform,
    );
  else return false;
  return true;
}

/**
 * The GPU batch of one layer.
 * @param {WebGL2RenderingContext} gl
 * @param {import('./scene.js').Layer} layer
 * @returns {Batch}
 */
export function batch(gl, layer) {
  const made = makeBatch(gl, layer);
  made.layer = `${layer.kind} ${layer.style}`;
  return made;
}

/** @param {WebGL2RenderingContext} gl @param {import('./scene.js').Layer} layer @returns {Batch} */
function makeBatch(gl, layer) {
  const style = STYLES[layer.style];
  if (!style) throw new Error(`unknown style "${layer.style}"`);
  const transform = layer.transform ?? undefined;
  if (layer.kind === 'mesh') {
    if (style.kind !== 'area') throw new Error(`style "${layer.style}" is not for meshes`);
    const front = [...rgb(style.color), style.alpha];
    const back = [...rgb(style.back), style.alpha];
    return new TriangleMesh(
      gl,
      layer.positions,
      /** @type {Uint32Array} */ (layer.indices),
      { front, back },
      transform,
      layer.normals,
    );
  }
  if (layer.kind === 'points') {
    if (style.kind !== 'point') throw new Error(`style "${layer.style}" is not for points`);
    return new PointBatch(gl, layer.positions, { color: rgba(style), size: style.size }, transform);
  }
  if (style.kind !== 'line') throw new Error(`style "${layer.style}" is not for lines`);
  const segments = layer.kind === 'polyline' ? polylineSegments(layer.positions, layer.closed) : layer.positions;
  return new LineBatch(gl, segments, { color: rgba(style), width: style.width, dash: style.dash }, transform);
}

/** How much two boxes overlap (0 none, 1 for boxes sharing about a label's area). */
function overlap(
  /** @type {{x: number, y: number, w: number, h: number}} */ a,
  /** @type {{x: number, y: number, w: number, h: number}} */ b,
) {
  const ox = Math.min(a.x + a.w, b.x + b.w) - Math.max(a.x, b.x);
  const oy = Math.min(a.y + a.h, b.y + b.h) - Math.max(a.y, b.y);
  return ox > 0 && oy > 0 ? (ox * oy) / Math.max(1, Math.min(a.w * a.h, b.w * b.h)) : 0;
}

/** The share of a screen segment p0 p1 that runs through a box (sampled at 12 points). */
function crossing(
  /** @type {{x: number, y: number, w: number, h: number}} */ box,
  /** @type {{x: number, y: number}} */ p0,
  /** @type {{x: number, y: number}} */ p1,
) {
  let inside = 0;
  for (let k = 0; k <= 12; k++) {
    const x = p0.x + ((p1.x - p0.x) * k) / 12,
      y = p0.y + ((p1.y - p0.y) * k) / 12;
    if (x > box.x - 2 && x < box.x + box.w + 2 && y > box.y - 2 && y < box.y + box.h + 2) inside++;
  }
  return inside / 13;
}

/** Whether a frame with a scene in it has been drawn on this page (ruledlab:first-frame). */
let firstFrame = false;

/** How long the camera must rest before the layers with a stand-in are drawn in full (ms). */
const REST = 180;

export class Viewer {
  /**
   * @param {HTMLCanvasElement} canvas
   * @param {HTMLElement} labelLayer  where the labels go (over the canvas)
   */
  constructor(canvas, labelLayer) {
    this.canvas = canvas;
    /** @internal */
    this.labelLayer = labelLayer;
    /** @internal */
    this.background = [...rgb(PALETTE.paper), 1];
    this.camera = new OrbitCamera();
    /** @internal @type {Batch[]} */
    this.batches = [];
    /** @internal @type {Array<Batch | null>} the stand-ins of the layers that have one (Layer.moving) */
    this.light = [];
    /** @internal Whether the camera is moving: the stand-ins are drawn. */
    this.moving = false;
    /** @internal Time between the last two frames drawn in a row (ms): a rest must be longer. */
    this.frameGap = 0;
    /** @internal */
    this.lastFrameAt = 0;
    /** @internal */
    this.restTimer = 0;
    /** @type {import('./scene.js').Built | null} */
    this.built = null;
    /** @internal @type {(() => {top: number, bottom: number}) | null} shares of the height that overlays cover, for fit() */
    this.insets = null;
    /** @internal */
    this.frames = 0;
    /** @internal */
    this.pending = false;
    /** @internal The animation frame requested (requestRender), to cancel when drawn sooner. */
    this.requested = 0;
    /** @internal Whether the first figure has been readied (prepareFirst). */
    this.warm = false;
    /** @internal Bumped whenever the batches change: part of the key of the frame in the framebuffer. */
    this.version = 0;
    /** @internal The key of the frame the framebuffer holds (drawFrame). */
    this.drawn = '';
    /** @internal Whether the last frame was drawn straight onto the canvas (no framebuffer of its size). */
    this.direct = false;
    /** @internal Whether `built` has changed since the batches were made (they are made at the next frame). */
    this.stale = false;
    /** @internal */
    this.lost = false;
    /** @internal */
    this.disposed = false;
    /** @type {((frames: number) => void) | null} */
    this.onFrame = null;
    /** @type {((ended: boolean) => void) | null} */
    this.onCameraChange = null;
    /** @internal @type {Array<(viewProj: Float32Array) => void>} what is placed over the view after each frame (the handles) */
    this.overlays = [];
    const gl = canvas.getContext('webgl2', {
      // the framebuffer is multisampled (gl/framebuffer.js): the canvas's own buffer is not; its
      // depth buffer serves a frame too large for the framebuffer (drawn straight onto the canvas)
      antialias: false,
      depth: true,
      alpha: false,
      preserveDrawingBuffer: false,
    });
    if (!gl)
      throw Object.assign(new Error('This page needs WebGL2, which this browser does not provide.'), {
        code: 'no-webgl2',
      });
    /** @internal */
    this.gl = gl;
    /** @internal The multisampled framebuffer frames are drawn into, then resolved onto the canvas. */
    this.framebuffer = new Framebuffer(gl);
    // the shaders compile on the GPU while the core loads and the first scene computes
    for (const prepare of [prepareLines, preparePoints, prepareMeshes]) prepare(gl);
    /** @internal */
    this.onLost = (/** @type {Event} */ e) => {
      e.preventDefault();
      this.lost = true;
      this.batches = [];
      this.light = [];
      this.framebuffer.forget();
      this.drawn = '';
    };
    /** @internal */
    this.onRestored = () => {
      this.lost = false;
      forgetPrograms(gl);
      for (const prepare of [prepareLines, preparePoints, prepareMeshes]) prepare(gl);
      this.rebuild();
    };
    canvas.addEventListener('webglcontextlost', this.onLost);
    canvas.addEventListener('webglcontextrestored', this.onRestored);
    this.camera.attach(canvas, (ended) => {
      this.moved();
      this.requestRender();
      this.onCameraChange?.(ended);
    });
    // a view resized while its camera is where fit() put it is framed again (a moved camera stays)
    /** @internal */
    this.resize = new ResizeObserver(() => {
      if (this.camera.atHome()) this.fit();
      this.requestRender();
    });
    this.resize.observe(canvas);
  }

  /** @internal Width / height of the view. */
  get aspect() {
    return (this.canvas.clientWidth || 1) / (this.canvas.clientHeight || 1);
  }

  /**
   * Shows `built`; `fit` reframes the camera on its bounds (from the scene's suggested direction).
   * @param {import('./scene.js').Built} built
   * @param {{fit?: boolean}} [options]
   */
  show(built, { fit = false } = {}) {
    this.built = built;
    if (fit) this.fit();
    this.stale = true;
    this.requestRender();
  }

  /** Frames the current scene from its suggested direction. */
  fit() {
    if (!this.built) return;
    if (this.built.camera) Object.assign(this.camera, this.built.camera);
    this.camera.fit(this.built.bounds, this.aspect, this.insets?.() ?? {});
    this.requestRender();
  }

  /** @internal Makes the batches (and the labels) of `built` now, and draws them at the next frame. */
  rebuild() {
    this.upload();
    this.requestRender();
  }

  /** @internal Makes the batches and the labels of `built`. */
  upload() {
    this.stale = false;
    this.version++;
    const gl = this.gl;
    this.labelLayer.replaceChildren(
      ...(this.built?.labels ?? []).map(({ text }) =>
        appendRich(Object.assign(document.createElement('span'), { className: 'rl-label' }), text),
      ),
    );
    const [before, lightBefore] = [this.batches, this.light];
    this.batches = [];
    this.light = [];
    const built = this.built;
    if (built && !this.lost && !this.disposed) {
      measured('ruledlab:upload', () => {
        built.layers.forEach((layer, i) => {
          // the batch of the same layer before, where it can take the new numbers
          const kept = reuse(gl, before[i], layer) ? before[i] : null;
          if (kept) before[i] = /** @type {any} */ (null);
          this.batches.push(kept ?? batch(gl, layer));
          const moving = layer.moving;
          const light = moving && reuse(gl, lightBefore[i], moving) ? lightBefore[i] : null;
          if (light) lightBefore[i] = null;
          this.light.push(light ?? (moving ? batch(gl, moving) : null));
        });
      });
    }
    for (const b of [...before, ...lightBefore]) b?.dispose(gl);
  }

  /**
   * The camera moved: draw the stand-ins until it has rested for REST ms (or two frame times,
   * when frames are slower than that), then everything.
   * @internal
   */
  moved() {
    if (!this.light.some(Boolean)) return;
    this.moving = true;
    const movedAt = this.frames;
    const rest = () => {
      // the move has not been drawn yet (a slow frame): rest only after it has
      if (this.frames === movedAt) {
        this.restTimer = window.setTimeout(rest, REST);
        return;
      }
      this.moving = false;
      this.requestRender();
    };
    clearTimeout(this.restTimer);
    this.restTimer = window.setTimeout(rest, Math.max(REST, 2 * this.frameGap));
  }

  requestRender() {
    if (this.pending || this.disposed) return;
    this.pending = true;
    const draw = () => {
      this.requested = requestAnimationFrame(() => {
        // the first figure is drawn and waited for before its frame (prepareFirst)
        if (!this.warm && this.built) {
          // (a failure there leaves the frame to the ordinary path, which says it)
          this.prepareFirst().then(draw, draw);
          return;
        }
        this.pending = false;
        this.render();
      });
    };
    draw();
  }

  /**
   * Draws now what a requested frame would draw, inside an animation frame already running (a
   * drag's computation): the requested frame is cancelled, so the move is drawn once.
   */
  renderNow() {
    if (!this.pending || !this.warm || this.disposed) return;
    cancelAnimationFrame(this.requested);
    this.pending = false;
    this.render();
  }

  /**
   * @internal Readies the first frame of a figure without blocking the page: the canvas sized
   * (and cleared, a frame of its own), then the figure drawn into the framebuffer while the GPU's
   * work — building the programs' code for their first draw, and the drawing — is waited for
   * between tasks (gl/fence.js). The frame that shows it resolves the framebuffer onto the canvas and
   * waits for nothing. On software WebGL that work took 60–200 ms here, every millisecond of it
   * blocking the page when the browser presented a frame still being drawn. Once per viewer.
   */
  async prepareFirst() {
    if (this.warm) return;
    this.warm = true;
    const { gl } = this;
    if (this.lost || this.disposed || !this.built) return;
    this.sizeCanvas(this.frame());
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.viewport(0, 0, this.canvas.width, this.canvas.height);
    gl.clearColor(this.background[0], this.background[1], this.background[2], 1);
    gl.clear(gl.COLOR_BUFFER_BIT);
    await afterPaint();
    if (this.lost || this.disposed || !this.built) return;
    if (this.stale) this.upload();
    const frame = this.frame();
    this.drawFrame(frame, this.moving);
    await finished(gl);
  }

  /**
   * @internal Draws the batches into the framebuffer (the stand-ins where `moving`), unless it
   * holds this very frame already (prepareFirst); the canvas is not touched.
   */
  drawFrame(/** @type {Frame} */ frame, /** @type {boolean} */ moving) {
    const { gl } = this;
    const key = `${frame.width} ${frame.height} ${frame.dpr} ${moving} ${this.version} ${frame.viewProj.join()}`;
    if (key === this.drawn && this.framebuffer.buffers) return;
    // (a size the GPU cannot make a framebuffer of is drawn straight onto the canvas, unresolved)
    this.direct = !this.framebuffer.bind(frame.width, frame.height);
    gl.viewport(0, 0, frame.width, frame.height);
    this.setState(this.background);
    measured('ruledlab:draw', () => this.drawBatches(frame, moving));
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    this.drawn = this.direct ? '' : key;
  }

  /** @internal Gives the canvas the frame's size in device pixels (a new size allocates its buffers). */
  sizeCanvas(/** @type {Frame} */ frame) {
    const { canvas } = this;
    if (canvas.width !== frame.width || canvas.height !== frame.height) {
      canvas.width = frame.width;
      canvas.height = frame.height;
    }
  }

  /** @internal The state every frame is drawn with, the framebuffer cleared to `background`. */
  setState(/** @type {number[]} */ background) {
    const { gl } = this;
    gl.clearColor(background[0], background[1], background[2], 1);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    gl.enable(gl.DEPTH_TEST);
    // ties go to the layer drawn later: a line drawn again in another style (a highlighted cell) shows
    gl.depthFunc(gl.LEQUAL);
    gl.enable(gl.BLEND);
    gl.blendFunc(gl.SRC_ALPHA, gl.ONE_MINUS_SRC_ALPHA);
  }

  /** @internal Draws the batches (the stand-ins where `moving`), opaque ones first. */
  drawBatches(/** @type {Frame} */ frame, /** @type {boolean} */ moving) {
    const { gl } = this;
    for (const transparent of [false, true]) {
      gl.depthMask(!transparent);
      this.batches.forEach((full, i) => {
        const b = (moving && this.light[i]) || full;
        if (!!b.transparent === transparent) b.draw(gl, frame);
      });
    }
    gl.depthMask(true);
  }

  /** @internal The frame's matrices and sizes for the current canvas size (`scale`: pixels per CSS pixel). */
  frame(scale = window.devicePixelRatio || 1) {
    const { canvas } = this;
    const dpr = scale;
    const width = Math.max(1, Math.round(canvas.clientWidth * dpr));
    const height = Math.max(1, Math.round(canvas.clientHeight * dpr));
    return { viewProj: this.camera.viewProj(width / height), eye: this.camera.eye, width, height, dpr };
  }

  /**
   * Draws now; `scale` renders at that many pixels per CSS pixel, `full` every layer in full
   * detail even while the camera moves (both for figure export). A figure's frame is drawn
   * afresh, never the target's frame resolved again: a canvas that only had a resolve since it
   * was shown is read by drawImage as black (Chromium), which made every PNG at 1× black.
   */
  render({ scale = window.devicePixelRatio || 1, full = false } = {}) {
    const { gl } = this;
    // (nothing to show yet: the canvas keeps the view's background, and no frame is read back)
    if (this.lost || this.disposed || !this.built || gl.isContextLost()) return;
    if (this.stale) this.upload();
    const frame = this.frame(scale);
    const moving = !full && this.moving;
    // what this frame shows, for tests and curious readers: the stand-ins or everything
    this.canvas.dataset.detail = moving && this.light.some(Boolean) ? 'stand-in' : 'full';
    // the time between frames drawn in a row (a rest must be longer than that)
    const now = performance.now();
    if (now - this.lastFrameAt < 2000) this.frameGap = now - this.lastFrameAt;
    this.lastFrameAt = now;
    this.sizeCanvas(frame);
    if (full) this.drawn = '';
    this.drawFrame(frame, moving);
    if (!this.direct) this.framebuffer.resolve();
    this.placeLabels(frame.viewProj);
    for (const overlay of this.overlays) overlay(frame.viewProj);
    this.frames++;
    if (!firstFrame && this.batches.length) {
      firstFrame = true;
      mark('ruledlab:first-frame');
      // the next frame begins once this one has been handed on: the time between the two marks
      // is the GPU's (and, where the page is composited in software, reading the frame back)
      requestAnimationFrame(() => mark('ruledlab:first-frame-presented'));
    }
    this.onFrame?.(this.frames);
  }

  /**
   * Moves each label next to the screen position of its anchor (hidden behind the camera).
   * A small collision pass picks, per label, the side of its anchor where it overlaps no label
   * placed before it and no line the scene wants kept clear (`built.keepClear`).
   * @internal
   */
  placeLabels(/** @type {Float32Array} */ m) {
    const labels = this.built?.labels ?? [];
    const { clientWidth: w, clientHeight: h } = this.canvas;
    const project = (/** @type {ArrayLike<number>} */ p, /** @type {number} */ o = 0) => {
      const [x, y, z] = [p[o], p[o + 1], p[o + 2]];
      const cw = m[3] * x + m[7] * y + m[11] * z + m[15];
      return {
        x: (((m[0] * x + m[4] * y + m[8] * z + m[12]) / cw + 1) / 2) * w,
        y: ((1 - (m[1] * x + m[5] * y + m[9] * z + m[13]) / cw) / 2) * h,
        visible: cw > 0,
      };
    };
    /** @type {Array<Array<{x: number, y: number, visible: boolean}>>} */
    const clear = [];
    const keep = this.built?.keepClear;
    for (let i = 0; keep && i + 5 < keep.length; i += 6) clear.push([project(keep, i), project(keep, i + 3)]);
    /** @type {Array<{x: number, y: number, w: number, h: number}>} */
    const placed = [];
    labels.forEach(({ at }, k) => {
      const el = /** @type {HTMLElement | undefined} */ (this.labelLayer.children[k]);
      if (!el) return;
      const a = project(at);
      el.hidden = !a.visible;
      if (!a.visible) return;
      const bw = el.offsetWidth,
        bh = el.offsetHeight;
      // candidate places: right above first, then around the anchor at growing distances
      const sides = [
        [7, -bh - 2],
        [7, 3],
        [-bw - 7, -bh - 2],
        [-bw - 7, 3],
      ];
      for (const d of [14, 26, 42]) {
        for (let k = 0; k < 12; k++) {
          const angle = (Math.PI * 2 * k) / 12;
          sides.push([Math.cos(angle) * (d + bw / 2) - bw / 2, -Math.sin(angle) * (d + bh / 2) - bh / 2]);
        }
      }
      let best = sides[0],
        bestCost = Infinity;
      sides.forEach(([dx, dy], rank) => {
        const box = { x: a.x + dx, y: a.y + dy, w: bw, h: bh };
        let cost = rank * 0.05;
        for (const q of placed) cost += 40 * overlap(box, q);
        for (const [p0, p1] of clear) cost += 30 * crossing(box, p0, p1);
        if (box.x < 0 || box.y < 0 || box.x + bw > w || box.y + bh > h) cost += 20;
        if (cost < bestCost) [best, bestCost] = [[dx, dy], cost];
      });
      const box = { x: a.x + best[0], y: a.y + best[1], w: bw, h: bh };
      placed.push(box);
      el.style.transform = `translate(${box.x}px, ${box.y}px)`;
    });
  }

  /** Frees every GPU object and gives the context back to the browser. */
  dispose() {
    if (this.disposed) return;
    const gl = this.gl;
    this.batches.forEach((b) => {
      b.dispose(gl);
    });
    this.light.forEach((b) => {
      b?.dispose(gl);
    });
    clearTimeout(this.restTimer);
    this.batches = [];
    this.light = [];
    this.framebuffer.dispose();
    forgetPrograms(gl);
    this.resize.disconnect();
    this.canvas.removeEventListener('webglcontextlost', this.onLost);
    this.canvas.removeEventListener('webglcontextrestored', this.onRestored);
    this.disposed = true;
    gl.getExtension('WEBGL_lose_context')?.loseContext();
  }
}
