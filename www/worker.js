// Heavy refinements off the main thread: a module worker with its own wasm instance.
// First message: { init: wasm source } (a URL, or the bytes in the one-file build).
// Then { id, segments: Float64Array, options, draw } (RuledSurface.subdivide options, steps
// included; `draw`: most rulings to send back). Messages out: { id, progress } after each
// step (by work done, later steps being larger), then { id, segments: Float32Array, rulings,
// drawn } (transferred; every k-th ruling when there are more than `draw`), or { id, error, code }.
import init, { RuledSurface } from '../pkg/ruledlab.js';

/** @type {Promise<unknown> | null} */
let ready = null;

self.onmessage = async ({ data }) => {
  if ('init' in data) {
    ready = init({ module_or_path: data.init });
    return;
  }
  const { id, segments, options, draw = Infinity } = data;
  /** @type {RuledSurface | null} */
  let surface = null;
  try {
    await ready;
    surface = RuledSurface.fromSegments(segments);
    const steps = options.steps ?? 1;
    const total = 2 ** steps - 1; // step k costs about 2^k
    for (let k = 0; k < steps; k++) {
      /** @type {RuledSurface} */
      const next = surface.subdivide({ ...options, steps: 1 });
      surface.free();
      surface = next;
      self.postMessage({ id, progress: (2 ** (k + 1) - 1) / total });
    }
    const rulings = surface.length;
    const every = Math.max(1, Math.ceil(rulings / draw));
    const out = every > 1 ? surface.everyF32(every) : surface.segmentsF32();
    self.postMessage({ id, segments: out, rulings, drawn: out.length / 6 }, { transfer: [out.buffer] });
  } catch (e) {
    const error = /** @type {any} */ (e);
    self.postMessage({ id, error: String(error?.message ?? error), code: error?.code });
  } finally {
    surface?.free();
  }
};
